#pragma once
// The editor's parameter panel: the header and one row per declared parameter of the selected
// section or element. Its rows come from SceneSchema; nothing here names a parameter, so a
// parameter declared in the engine appears in the panel without a line of UI code. It follows the
// document: undo, redo and edits from other widgets update its fields, and it moves to the
// element's new index or clears when elements are inserted, removed or the scene is replaced.
#include "document/SceneItem.h"

#include <QWidget>
#include <vector>

class QLabel;
class QScrollArea;

namespace airtrap {

class ParameterRow;
class SceneDocument;

class ParameterPanel : public QWidget {
    Q_OBJECT

public:
    //! A panel editing `document`'s scene, showing nothing until showItem().
    explicit ParameterPanel(SceneDocument& document, QWidget* parent = nullptr);

    //! The item shown; None when nothing is, or after the shown element was removed.
    const SceneItem& item() const { return item_; }

public Q_SLOTS:
    //! Shows `item`: a section's or element's parameters, a group's summary, or a hint for None
    //! or an item the scene does not hold. Showing the shown item again only refreshes it.
    void showItem(const airtrap::SceneItem& item);

private:
    void rebuild();
    void updateHeader();
    void replaceRows();
    QString groupSummary() const;
    void onParameterChanged(const SceneItem& item, const QString& key);
    void onElementInserted(const QString& section, int index);
    void onElementRemoved(const QString& section, int index);
    void onReset();

    SceneDocument& document_;
    SceneItem item_;
    QLabel* title_ = nullptr;
    QLabel* subtitle_ = nullptr;
    QScrollArea* scrollArea_ = nullptr;
    std::vector<ParameterRow*> rows_;
};

} // namespace airtrap
