#include "panels/ParameterPanel.h"

#include "document/SceneDocument.h"
#include "panels/ParameterRow.h"
#include "scene/SceneSchema.h"

#include <QGridLayout>
#include <QLabel>
#include <QScrollArea>
#include <QVBoxLayout>

namespace airtrap {

namespace {

constexpr auto kNameKey = "name";
constexpr double kTitleScale = 1.25;

QLabel* createTitle(QWidget* parent) {
    auto* title = new QLabel(parent);
    title->setObjectName(QStringLiteral("title"));
    QFont font = title->font();
    font.setBold(true);
    font.setPointSizeF(font.pointSizeF() * kTitleScale);
    title->setFont(font);
    title->setWordWrap(true);
    return title;
}

QLabel* createSubtitle(QWidget* parent) {
    auto* subtitle = new QLabel(parent);
    subtitle->setObjectName(QStringLiteral("subtitle"));
    subtitle->setWordWrap(true);
    return subtitle;
}

} // namespace

ParameterPanel::ParameterPanel(SceneDocument& document, QWidget* parent)
    : QWidget(parent), document_(document), title_(createTitle(this)),
      subtitle_(createSubtitle(this)), scrollArea_(new QScrollArea(this)) {
    scrollArea_->setObjectName(QStringLiteral("parameterScrollArea"));
    scrollArea_->setWidgetResizable(true);
    scrollArea_->setFrameShape(QFrame::NoFrame);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(title_);
    layout->addWidget(subtitle_);
    layout->addWidget(scrollArea_, 1);

    connect(&document_, &SceneDocument::parameterChanged, this,
            &ParameterPanel::onParameterChanged);
    connect(&document_, &SceneDocument::elementInserted, this, &ParameterPanel::onElementInserted);
    connect(&document_, &SceneDocument::elementRemoved, this, &ParameterPanel::onElementRemoved);
    connect(&document_, &SceneDocument::reset, this, &ParameterPanel::onReset);
    rebuild();
}

void ParameterPanel::showItem(const SceneItem& item) {
    const SceneItem shown = document_.contains(item) ? item : SceneItem::none();
    if (shown == item_ && (!rows_.empty() || !item_.hasParameters())) {
        updateHeader();
        for (ParameterRow* row : rows_)
            row->refresh();
        return;
    }
    item_ = shown;
    rebuild();
}

void ParameterPanel::rebuild() {
    updateHeader();
    replaceRows();
}

void ParameterPanel::updateHeader() {
    title_->setVisible(!item_.isNone());
    if (item_.isNone()) {
        subtitle_->setText(
            tr("Select the scene, a section or an element in the scene tree to edit it."));
        return;
    }
    const SchemaSection& section = SceneDocument::sectionOf(item_.section);
    title_->setText(document_.elementName(item_));
    const QString help = QString::fromStdString(section.help);
    subtitle_->setText(item_.kind == SceneItem::Kind::Group
                           ? help + QStringLiteral("\n\n") + groupSummary()
                           : help);
}

QString ParameterPanel::groupSummary() const {
    const SchemaSection& section = SceneDocument::sectionOf(item_.section);
    const std::size_t count = section.elementCount(document_.scene());
    const std::string& noun = count == 1 ? section.elementLabel : section.label;
    return tr("The scene has %1 %2.").arg(count).arg(QString::fromStdString(noun).toLower());
}

void ParameterPanel::replaceRows() {
    rows_.clear();
    // Later, not now: this can run inside a signal sent by one of the old rows' widgets.
    if (QWidget* old = scrollArea_->takeWidget())
        old->deleteLater();
    auto* content = new QWidget;
    content->setObjectName(QStringLiteral("parameterRows"));
    auto* grid = new QGridLayout(content);
    grid->setColumnStretch(1, 1);
    int gridRow = 0;
    if (item_.hasParameters()) {
        for (const BoundParameter& parameter : SceneDocument::sectionOf(item_.section).parameters) {
            rows_.push_back(
                new ParameterRow(document_, item_, parameter.declaration, *grid, gridRow));
            gridRow += 2;
        }
    }
    grid->setRowStretch(gridRow, 1);
    scrollArea_->setWidget(content);
}

void ParameterPanel::onParameterChanged(const SceneItem& item, const QString& key) {
    if (item != item_)
        return;
    const std::string changedKey = key.toStdString();
    for (ParameterRow* row : rows_)
        if (row->key() == changedKey)
            row->refresh();
    // A new shape shows its own fields (a sphere's radius) and hides the old one's.
    for (ParameterRow* row : rows_)
        row->showIfApplies();
    if (changedKey == kNameKey)
        updateHeader();
}

void ParameterPanel::onElementInserted(const QString& section, int index) {
    if (section.toStdString() != item_.section)
        return;
    if (item_.kind == SceneItem::Kind::Group) {
        updateHeader();
    } else if (item_.kind == SceneItem::Kind::Element &&
               static_cast<std::size_t>(index) <= item_.element) {
        // The shown element moved one place down; keep showing it, not its new neighbour.
        ++item_.element;
        rebuild();
    }
}

void ParameterPanel::onElementRemoved(const QString& section, int index) {
    if (section.toStdString() != item_.section)
        return;
    if (item_.kind == SceneItem::Kind::Group) {
        updateHeader();
        return;
    }
    if (item_.kind != SceneItem::Kind::Element)
        return;
    const auto removed = static_cast<std::size_t>(index);
    if (removed == item_.element)
        item_ = SceneItem::none();
    else if (removed < item_.element)
        --item_.element;
    else
        return;
    rebuild();
}

void ParameterPanel::onReset() {
    // Another scene: an element index of the old one means nothing in it; sections remain.
    if (item_.kind == SceneItem::Kind::Element || !document_.contains(item_))
        item_ = SceneItem::none();
    rebuild();
}

} // namespace airtrap
