#pragma once
// The editor's main window. Today it holds the menus and an empty viewport; the scene tree,
// parameter panels and timeline join it as the editor grows.
#include <QMainWindow>
#include <QString>

class QAction;
class QMenu;

namespace airtrap {

class ViewportWidget;

class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);

    ViewportWidget* viewport() const { return viewport_; }
    QMenu* fileMenu() const { return fileMenu_; }
    QAction* openSceneAction() const { return openSceneAction_; }
    QAction* quitAction() const { return quitAction_; }

public Q_SLOTS:
    //! Reads the scene file at `path` just far enough to name it in the status bar. Returns false
    //! (and says why in the status bar) when the file cannot be read or is not a JSON object.
    bool openScene(const QString& path);

protected:
    void closeEvent(QCloseEvent* event) override;

private Q_SLOTS:
    void chooseScene();
    void showAbout();

private:
    void createMenus();
    void restoreSettings();
    void saveSettings() const;

    ViewportWidget* viewport_ = nullptr;
    QMenu* fileMenu_ = nullptr;
    QAction* openSceneAction_ = nullptr;
    QAction* quitAction_ = nullptr;
};

} // namespace airtrap
