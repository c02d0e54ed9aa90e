#include "panels/ParameterRow.h"

#include "document/SceneDocument.h"
#include "panels/ParameterEditor.h"
#include "panels/ParameterEditorFactory.h"
#include "scene/ParameterCodec.h"

#include <QAction>
#include <QGridLayout>
#include <QIcon>
#include <QLabel>
#include <QStyle>
#include <QToolButton>
#include <algorithm>

namespace airtrap {

namespace {

enum GridColumn { kLabelColumn = 0, kEditorColumn = 1, kResetColumn = 2 };

constexpr auto kErrorStyle = "color: #d32f2f;";

bool hasUnitInRange(ParameterKind kind) {
    return kind == ParameterKind::Int || kind == ParameterKind::Real ||
           kind == ParameterKind::Vector3;
}

} // namespace

ParameterRow::ParameterRow(SceneDocument& document, SceneItem item,
                           ParameterDeclaration declaration, QGridLayout& grid, int gridRow)
    : QObject(grid.parentWidget()), document_(document), item_(std::move(item)),
      declaration_(std::move(declaration)) {
    QWidget* parent = grid.parentWidget();
    editor_ = ParameterEditorFactory::create(declaration_, parent);
    editor_->setToolTip(toolTip());
    QLabel* label = createLabel(parent);
    QToolButton* resetButton = createResetButton(parent);
    label_ = label;
    resetButton_ = resetButton;
    // The reset action also sits in the label's context menu, where users look for it first.
    label->setContextMenuPolicy(Qt::ActionsContextMenu);
    label->addAction(resetAction_);
    errorLabel_ = createErrorLabel(parent);

    grid.addWidget(label, gridRow, kLabelColumn);
    grid.addWidget(editor_, gridRow, kEditorColumn);
    grid.addWidget(resetButton, gridRow, kResetColumn);
    grid.addWidget(errorLabel_, gridRow + 1, kEditorColumn, 1, 2);

    connect(editor_, &ParameterEditor::edited, this, &ParameterRow::commit);
    connect(editor_, &ParameterEditor::dragStarted, this, &ParameterRow::startDrag);
    connect(editor_, &ParameterEditor::dragFinished, this, &ParameterRow::finishDrag);
    refresh();
    showIfApplies();
}

bool ParameterRow::applies() const {
    if (declaration_.appliesWhenKey.empty())
        return true;
    const ParameterValue selector = document_.parameter(item_, declaration_.appliesWhenKey);
    const auto* choice = std::get_if<std::string>(&selector);
    const std::vector<std::string>& values = declaration_.appliesWhenValues;
    return choice != nullptr && std::find(values.begin(), values.end(), *choice) != values.end();
}

void ParameterRow::showIfApplies() {
    const bool shown = applies();
    label_->setVisible(shown);
    editor_->setVisible(shown);
    resetButton_->setVisible(shown);
    // The refusal line only ever shows under a shown row.
    if (!shown)
        errorLabel_->hide();
}

QLabel* ParameterRow::createLabel(QWidget* parent) const {
    QString text = QString::fromStdString(declaration_.label);
    if (!declaration_.unit.empty())
        text += QStringLiteral(" (%1)").arg(QString::fromStdString(declaration_.unit));
    auto* label = new QLabel(text, parent);
    label->setObjectName(QStringLiteral("label_%1").arg(QString::fromStdString(key())));
    label->setToolTip(toolTip());
    label->setBuddy(editor_);
    return label;
}

QToolButton* ParameterRow::createResetButton(QWidget* parent) {
    const QString defaultText = withUnit(ParameterCodec::formatValue(declaration_.defaultValue));
    resetAction_ = new QAction(tr("Reset to Default (%1)").arg(defaultText), this);
    resetAction_->setObjectName(QStringLiteral("reset_%1").arg(QString::fromStdString(key())));
    resetAction_->setIcon(
        QIcon::fromTheme(QStringLiteral("document-revert"),
                         parent->style()->standardIcon(QStyle::SP_BrowserReload)));
    connect(resetAction_, &QAction::triggered, this,
            [this] { commit(declaration_.defaultValue, false); });

    auto* button = new QToolButton(parent);
    // Icon only: the action's text and tooltip name the default, and the button follows the
    // action's enabled state.
    button->setDefaultAction(resetAction_);
    button->setAutoRaise(true);
    button->setFocusPolicy(Qt::NoFocus);
    return button;
}

QLabel* ParameterRow::createErrorLabel(QWidget* parent) const {
    auto* label = new QLabel(parent);
    label->setObjectName(QStringLiteral("error_%1").arg(QString::fromStdString(key())));
    label->setStyleSheet(QString::fromLatin1(kErrorStyle));
    label->setWordWrap(true);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    label->hide();
    return label;
}

void ParameterRow::refresh() {
    errorLabel_->hide();
    showDocumentValue();
}

void ParameterRow::commit(const ParameterValue& value, bool dragging) {
    const int session = dragging ? dragSession_ : 0;
    const QString reason = document_.editParameter(item_, key(), value, session);
    if (reason.isEmpty())
        errorLabel_->hide();
    else
        showRefusal(reason);
    // Also after a success: the document may hold the value in its own form (an integer typed
    // into a number field), and an unchanged value sends no parameterChanged to refresh with.
    showDocumentValue();
}

void ParameterRow::startDrag() {
    dragSession_ = document_.newDragSession();
}

void ParameterRow::finishDrag() {
    dragSession_ = 0;
    // The handle was left alone during the drag; now it may snap to the value it stands for.
    showDocumentValue();
}

void ParameterRow::showDocumentValue() {
    // The item can vanish under a pending edit (the panel rebuilds on the next signal).
    if (!document_.contains(item_))
        return;
    const ParameterValue value = document_.parameter(item_, key());
    editor_->setValue(value);
    resetAction_->setEnabled(value != declaration_.defaultValue);
}

void ParameterRow::showRefusal(const QString& reason) {
    errorLabel_->setText(reason);
    errorLabel_->show();
}

QString ParameterRow::toolTip() const {
    QString text = QString::fromStdString(declaration_.help);
    text += QStringLiteral("\n") +
            tr("Allowed: %1").arg(withUnit(ParameterCodec::rangeText(declaration_)));
    text += QStringLiteral("\n") +
            tr("Default: %1").arg(withUnit(ParameterCodec::formatValue(declaration_.defaultValue)));
    return text;
}

QString ParameterRow::withUnit(const std::string& text) const {
    QString result = QString::fromStdString(text);
    if (hasUnitInRange(declaration_.kind) && !declaration_.unit.empty())
        result += QStringLiteral(" ") + QString::fromStdString(declaration_.unit);
    return result;
}

} // namespace airtrap
