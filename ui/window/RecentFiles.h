#pragma once
// The File ▸ Open Recent menu, remembered across sessions in the editor's settings. Files that no
// longer exist leave it; two scenes of one name are told apart by their folders.
#include <QObject>
#include <QStringList>

class QMenu;

namespace airtrap {

class RecentFiles : public QObject {
    Q_OBJECT

public:
    static constexpr int kMaximumEntries = 10;

    //! `menu` is filled and kept up to date; it is not owned.
    RecentFiles(QMenu* menu, QObject* parent = nullptr);

    QStringList files() const { return files_; }
    //! Moves `path` to the top of the list (adding it when new) and saves the list.
    void add(const QString& path);
    //! Drops `path` (a file that could not be opened any more).
    void remove(const QString& path);

    //! The menu's text for `path`: its file name, with its folder when another listed file has
    //! the same name.
    QString label(const QString& path) const;

Q_SIGNALS:
    void fileChosen(const QString& path);

private:
    void save() const;
    void rebuildMenu();
    //! Forgets the files that no longer exist; true when there were any.
    bool dropMissing();

    QMenu* menu_;
    QStringList files_;
};

} // namespace airtrap
