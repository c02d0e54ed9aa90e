#include "model/SceneTreeModel.h"

#include "document/SceneDocument.h"
#include "scene/SceneSchema.h"

#include <QApplication>
#include <QFont>
#include <QStyle>

namespace airtrap {

namespace {

// Internal ids: 0 marks a top-level (section) row; an element row stores its section's row + 1,
// which is all parent() needs.
constexpr quintptr kSectionRowId = 0;

const std::vector<SchemaSection>& sections() {
    return SceneSchema::sections();
}

} // namespace

SceneTreeModel::SceneTreeModel(SceneDocument& document, QObject* parent)
    : QAbstractItemModel(parent), document_(document) {
    connectDocument();
}

void SceneTreeModel::connectDocument() {
    connect(&document_, &SceneDocument::aboutToReset, this, [this] { beginResetModel(); });
    connect(&document_, &SceneDocument::reset, this, [this] { endResetModel(); });
    connect(&document_, &SceneDocument::elementAboutToBeInserted, this,
            [this](const QString& section, int row) {
                beginInsertRows(index(sectionRow(section), 0), row, row);
            });
    connect(&document_, &SceneDocument::elementInserted, this, [this] { endInsertRows(); });
    connect(&document_, &SceneDocument::elementAboutToBeRemoved, this,
            [this](const QString& section, int row) {
                beginRemoveRows(index(sectionRow(section), 0), row, row);
            });
    connect(&document_, &SceneDocument::elementRemoved, this, [this] { endRemoveRows(); });
    connect(&document_, &SceneDocument::parameterChanged, this,
            [this](const SceneItem& item, const QString& key) {
                if (key != QLatin1String("name"))
                    return;
                const QModelIndex changed = indexOf(item);
                Q_EMIT dataChanged(changed, changed);
            });
}

int SceneTreeModel::sectionRow(const QString& sectionKey) {
    const std::string key = sectionKey.toStdString();
    for (std::size_t row = 0; row < sections().size(); ++row)
        if (sections()[row].key == key)
            return static_cast<int>(row);
    return -1;
}

QModelIndex SceneTreeModel::index(int row, int column, const QModelIndex& parent) const {
    if (!hasIndex(row, column, parent))
        return {};
    if (!parent.isValid())
        return createIndex(row, column, kSectionRowId);
    return createIndex(row, column, static_cast<quintptr>(parent.row()) + 1);
}

QModelIndex SceneTreeModel::parent(const QModelIndex& child) const {
    if (!child.isValid() || child.internalId() == kSectionRowId)
        return {};
    return createIndex(static_cast<int>(child.internalId() - 1), 0, kSectionRowId);
}

int SceneTreeModel::rowCount(const QModelIndex& parent) const {
    if (!parent.isValid())
        return static_cast<int>(sections().size());
    if (parent.column() != 0 || parent.internalId() != kSectionRowId)
        return 0;
    const SchemaSection& section = sections()[static_cast<std::size_t>(parent.row())];
    return section.isArray ? static_cast<int>(section.elementCount(document_.scene())) : 0;
}

int SceneTreeModel::columnCount(const QModelIndex&) const {
    return 1;
}

SceneItem SceneTreeModel::itemAt(const QModelIndex& index) const {
    if (!index.isValid())
        return SceneItem::none();
    if (index.internalId() == kSectionRowId) {
        const SchemaSection& section = sections()[static_cast<std::size_t>(index.row())];
        return section.isArray ? SceneItem::group(section.key)
                               : SceneItem::sectionItem(section.key);
    }
    const SchemaSection& section = sections()[index.internalId() - 1];
    return SceneItem::elementItem(section.key, static_cast<std::size_t>(index.row()));
}

QModelIndex SceneTreeModel::indexOf(const SceneItem& item) const {
    if (!document_.contains(item))
        return {};
    const QModelIndex sectionIndex = index(sectionRow(QString::fromStdString(item.section)), 0);
    if (item.kind != SceneItem::Kind::Element)
        return sectionIndex;
    return index(static_cast<int>(item.element), 0, sectionIndex);
}

QString SceneTreeModel::displayText(const SceneItem& item) const {
    if (item.kind == SceneItem::Kind::Section && item.section.empty())
        return tr("Scene “%1”").arg(QString::fromStdString(document_.scene().name));
    return document_.elementName(item);
}

QVariant SceneTreeModel::data(const QModelIndex& index, int role) const {
    const SceneItem item = itemAt(index);
    if (item.isNone())
        return {};
    const SchemaSection& section = SceneDocument::sectionOf(item.section);
    switch (role) {
    case Qt::DisplayRole:
        return displayText(item);
    case Qt::EditRole:
        return document_.elementName(item);
    case Qt::ToolTipRole:
        return QString::fromStdString(section.help);
    case Qt::FontRole:
        if (item.kind == SceneItem::Kind::Group) {
            QFont bold;
            bold.setBold(true);
            return bold;
        }
        return {};
    case Qt::DecorationRole:
        return QApplication::style()->standardIcon(
            item.kind == SceneItem::Kind::Element ? QStyle::SP_FileIcon : QStyle::SP_DirIcon);
    default:
        return {};
    }
}

bool SceneTreeModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    const SceneItem item = itemAt(index);
    if (role != Qt::EditRole || item.kind != SceneItem::Kind::Element)
        return false;
    const QString reason = document_.renameElement(item, value.toString());
    if (!reason.isEmpty()) {
        Q_EMIT editRefused(reason);
        return false;
    }
    return true;
}

Qt::ItemFlags SceneTreeModel::flags(const QModelIndex& index) const {
    if (!index.isValid())
        return Qt::NoItemFlags;
    Qt::ItemFlags result = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    const SceneItem item = itemAt(index);
    if (item.kind == SceneItem::Kind::Element &&
        SceneDocument::sectionOf(item.section).find("name") != nullptr)
        result |= Qt::ItemIsEditable;
    return result;
}

} // namespace airtrap
