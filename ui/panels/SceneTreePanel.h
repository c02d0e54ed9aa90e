#pragma once
// The scene tree dock's content: the tree view over SceneTreeModel, with Add (one entry per kind
// of element the schema declares; a submenu of shapes for bodies), Duplicate and Remove, in a
// small toolbar and a context menu.
#include "document/SceneItem.h"

#include <QWidget>

class QMenu;
class QToolButton;
class QTreeView;

namespace airtrap {

class BodyAddMenu;
class SceneDocument;
class SceneTreeModel;

class SceneTreePanel : public QWidget {
    Q_OBJECT

public:
    SceneTreePanel(SceneDocument& document, QWidget* parent = nullptr);

    QTreeView* view() const { return view_; }
    SceneTreeModel* model() const { return model_; }
    //! The "Add" menu: one action per array section ("Fluid block", "Obstacle", …), and the
    //! Body submenu.
    QMenu* addMenu() const { return addMenu_; }
    //! Add ▸ Body: one action per body shape.
    BodyAddMenu* bodyMenu() const { return bodyMenu_; }

    SceneItem selectedItem() const;

public Q_SLOTS:
    //! Selects and reveals `item` without emitting itemSelected for a selection already there.
    void selectItem(const airtrap::SceneItem& item);
    void duplicateSelected();
    void removeSelected();
    void renameSelected();

Q_SIGNALS:
    void itemSelected(const airtrap::SceneItem& item);
    //! A rename or other edit was refused, with the reason.
    void editRefused(const QString& reason);

private:
    void buildToolbar();
    void buildAddMenu();
    void showContextMenu(const QPoint& position);
    void updateButtons();

    SceneDocument& document_;
    SceneTreeModel* model_;
    QTreeView* view_;
    QMenu* addMenu_;
    BodyAddMenu* bodyMenu_ = nullptr;
    QToolButton* duplicateButton_ = nullptr;
    QToolButton* removeButton_ = nullptr;
};

} // namespace airtrap
