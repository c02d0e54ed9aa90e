#include "panels/SceneTreePanel.h"

#include "document/SceneDocument.h"
#include "model/SceneTreeModel.h"
#include "panels/BodyAddMenu.h"
#include "scene/SceneSchema.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QMenu>
#include <QToolButton>
#include <QTreeView>
#include <QVBoxLayout>

namespace airtrap {

SceneTreePanel::SceneTreePanel(SceneDocument& document, QWidget* parent)
    : QWidget(parent), document_(document), model_(new SceneTreeModel(document, this)),
      view_(new QTreeView(this)), addMenu_(new QMenu(tr("&Add"), this)) {
    setObjectName(QStringLiteral("sceneTreePanel"));
    view_->setObjectName(QStringLiteral("sceneTree"));
    view_->setModel(model_);
    view_->setHeaderHidden(true);
    view_->setSelectionMode(QAbstractItemView::SingleSelection);
    view_->setEditTriggers(QAbstractItemView::EditKeyPressed | QAbstractItemView::SelectedClicked);
    view_->setContextMenuPolicy(Qt::CustomContextMenu);
    view_->expandAll();
    buildAddMenu();

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    buildToolbar();
    layout->addWidget(view_);

    connect(view_->selectionModel(), &QItemSelectionModel::currentChanged, this, [this] {
        updateButtons();
        Q_EMIT itemSelected(selectedItem());
    });
    connect(view_, &QTreeView::customContextMenuRequested, this, &SceneTreePanel::showContextMenu);
    connect(model_, &SceneTreeModel::editRefused, this, &SceneTreePanel::editRefused);
    // New rows (added, undone removals) and new documents are shown unfolded.
    connect(model_, &QAbstractItemModel::rowsInserted, view_,
            [this](const QModelIndex& insertedUnder) { view_->expand(insertedUnder); });
    connect(model_, &QAbstractItemModel::modelReset, view_, &QTreeView::expandAll);
    updateButtons();
}

void SceneTreePanel::buildAddMenu() {
    addMenu_->setObjectName(QStringLiteral("addMenu"));
    for (const SchemaSection& section : SceneSchema::sections()) {
        if (!section.isArray)
            continue;
        if (section.key == "bodies") {
            // A body is mostly its shape: each shape is its own entry, with its own first size.
            bodyMenu_ = new BodyAddMenu(document_, this);
            bodyMenu_->menuAction()->setStatusTip(QString::fromStdString(section.help));
            addMenu_->addMenu(bodyMenu_);
            connect(bodyMenu_, &BodyAddMenu::bodyAdded, this, &SceneTreePanel::selectItem);
            continue;
        }
        QAction* action = addMenu_->addAction(QString::fromStdString(section.elementLabel));
        action->setObjectName(QStringLiteral("add_") + QString::fromStdString(section.key));
        action->setStatusTip(QString::fromStdString(section.help));
        const std::string key = section.key;
        connect(action, &QAction::triggered, this,
                [this, key] { selectItem(document_.addElement(key)); });
    }
}

void SceneTreePanel::buildToolbar() {
    auto* bar = new QHBoxLayout;
    bar->setContentsMargins(2, 2, 2, 0);
    auto* addButton = new QToolButton(this);
    addButton->setText(tr("Add"));
    addButton->setObjectName(QStringLiteral("addButton"));
    addButton->setMenu(addMenu_);
    addButton->setPopupMode(QToolButton::InstantPopup);
    duplicateButton_ = new QToolButton(this);
    duplicateButton_->setText(tr("Duplicate"));
    duplicateButton_->setObjectName(QStringLiteral("duplicateButton"));
    connect(duplicateButton_, &QToolButton::clicked, this, &SceneTreePanel::duplicateSelected);
    removeButton_ = new QToolButton(this);
    removeButton_->setText(tr("Remove"));
    removeButton_->setObjectName(QStringLiteral("removeButton"));
    connect(removeButton_, &QToolButton::clicked, this, &SceneTreePanel::removeSelected);
    bar->addWidget(addButton);
    bar->addWidget(duplicateButton_);
    bar->addWidget(removeButton_);
    bar->addStretch();
    static_cast<QVBoxLayout*>(layout())->addLayout(bar);
}

SceneItem SceneTreePanel::selectedItem() const {
    return model_->itemAt(view_->currentIndex());
}

void SceneTreePanel::selectItem(const SceneItem& item) {
    const QModelIndex index = model_->indexOf(item);
    if (index == view_->currentIndex())
        return;
    if (!index.isValid()) {
        view_->selectionModel()->clear();
        return;
    }
    view_->setCurrentIndex(index);
    view_->scrollTo(index);
}

void SceneTreePanel::duplicateSelected() {
    selectItem(document_.duplicateElement(selectedItem()));
}

void SceneTreePanel::removeSelected() {
    const SceneItem item = selectedItem();
    if (item.kind != SceneItem::Kind::Element)
        return;
    document_.removeElement(item);
}

void SceneTreePanel::renameSelected() {
    const QModelIndex index = view_->currentIndex();
    if (model_->flags(index).testFlag(Qt::ItemIsEditable))
        view_->edit(index);
}

void SceneTreePanel::showContextMenu(const QPoint& position) {
    const QModelIndex index = view_->indexAt(position);
    if (index.isValid())
        view_->setCurrentIndex(index);
    const SceneItem item = selectedItem();
    QMenu menu(this);
    menu.addMenu(addMenu_);
    if (item.kind == SceneItem::Kind::Element) {
        menu.addAction(tr("Rename"), this, &SceneTreePanel::renameSelected);
        menu.addAction(tr("Duplicate"), this, &SceneTreePanel::duplicateSelected);
        menu.addAction(tr("Remove"), this, &SceneTreePanel::removeSelected);
    }
    menu.exec(view_->viewport()->mapToGlobal(position));
}

void SceneTreePanel::updateButtons() {
    const bool element = selectedItem().kind == SceneItem::Kind::Element;
    duplicateButton_->setEnabled(element);
    removeButton_->setEnabled(element);
}

} // namespace airtrap
