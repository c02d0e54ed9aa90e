#pragma once
// The scene tree: one row per schema section (Scene, Solver, Frames, Container, Fluid blocks,
// Obstacles, and whatever sections later versions declare), with the elements of array sections
// as children. Built from SceneSchema, so a new kind of object needs no change here.
#include "document/SceneItem.h"

#include <QAbstractItemModel>

namespace airtrap {

class SceneDocument;

class SceneTreeModel : public QAbstractItemModel {
    Q_OBJECT

public:
    explicit SceneTreeModel(SceneDocument& document, QObject* parent = nullptr);

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    //! Renames an element (Qt::EditRole); a refused name leaves it and emits editRefused.
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;

    //! The scene item a row stands for (SceneItem::none() for an invalid index).
    SceneItem itemAt(const QModelIndex& index) const;
    //! The row of an item; invalid when the scene has no such item.
    QModelIndex indexOf(const SceneItem& item) const;

Q_SIGNALS:
    //! A rename was refused; `reason` is the declaration's message.
    void editRefused(const QString& reason);

private:
    void connectDocument();
    //! Row of a section among the top-level rows; -1 when unknown.
    static int sectionRow(const QString& sectionKey);
    QString displayText(const SceneItem& item) const;

    SceneDocument& document_;
};

} // namespace airtrap
