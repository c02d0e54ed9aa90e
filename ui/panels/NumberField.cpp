#include "panels/NumberField.h"

#include "panels/CommittedFieldShortcuts.h"
#include "panels/DecimalRounding.h"
#include "scene/ParameterCodec.h"

#include <QLineEdit>
#include <QLocale>
#include <QSignalBlocker>
#include <cmath>

namespace airtrap {

namespace {

//! Far beyond every declared range, so the field never clamps what the user typed.
constexpr double kWidestMagnitude = 1e300;
//! QDoubleSpinBox rounds every value to its decimals; this many keep any double unchanged.
constexpr int kExactDecimals = 323;
//! The step from zero, where a tenth of the number's power of ten does not exist.
constexpr double kStepFromZero = 0.01;

bool isNumberCharacter(QChar character, bool integer) {
    if (character.isDigit() || character == u'-' || character == u'+' || character == u' ')
        return true;
    return !integer &&
           (character == u'.' || character == u',' || character == u'e' || character == u'E');
}

} // namespace

NumberField::NumberField(bool integer, QWidget* parent)
    : QDoubleSpinBox(parent), integer_(integer) {
    // Scene files and messages write numbers with a decimal point, whatever the desktop's locale.
    setLocale(QLocale::c());
    setDecimals(integer_ ? 0 : kExactDecimals);
    setRange(-kWidestMagnitude, kWidestMagnitude);
    setKeyboardTracking(false);
    setCorrectionMode(QAbstractSpinBox::CorrectToPreviousValue);
    connect(this, &QAbstractSpinBox::editingFinished, this, &NumberField::commitTypedText);
    // The spin box has the focus and forwards key events to its line edit: watch both.
    CommittedFieldShortcuts::install(this, lineEdit());
    CommittedFieldShortcuts::install(lineEdit(), lineEdit());
}

void NumberField::setNumber(double number) {
    shown_ = number;
    const QSignalBlocker blocker(this);
    setValue(number);
    // setValue() leaves the text alone when the value is unchanged but the text was edited.
    lineEdit()->setText(textFromValue(number));
}

void NumberField::stepBy(int steps) {
    const double from = parsed(cleanText()).value_or(shown_);
    const double step = stepFrom(from);
    const double to = integer_ ? from + steps : roundedToStep(from + steps * step, step);
    {
        const QSignalBlocker blocker(this);
        setValue(to);
    }
    if (to != shown_)
        Q_EMIT committed(to);
}

QValidator::State NumberField::validate(QString& input, int&) const {
    for (const QChar character : input)
        if (!isNumberCharacter(character, integer_))
            return QValidator::Invalid;
    return parsed(input) ? QValidator::Acceptable : QValidator::Intermediate;
}

void NumberField::fixup(QString& input) const {
    input = textFromValue(shown_);
}

QString NumberField::textFromValue(double value) const {
    return QString::fromStdString(ParameterCodec::formatNumber(value));
}

double NumberField::valueFromText(const QString& text) const {
    return parsed(text).value_or(shown_);
}

QAbstractSpinBox::StepEnabled NumberField::stepEnabled() const {
    return isReadOnly() ? StepNone : (StepUpEnabled | StepDownEnabled);
}

void NumberField::commitTypedText() {
    const std::optional<double> typed = parsed(cleanText());
    if (!typed || *typed == shown_) {
        setNumber(shown_);
        return;
    }
    Q_EMIT committed(*typed);
}

std::optional<double> NumberField::parsed(const QString& text) const {
    // A comma is taken for a decimal point: users of comma locales type it out of habit.
    QString normalised = text.trimmed();
    normalised.replace(u',', u'.');
    bool ok = false;
    const double number = integer_ ? static_cast<double>(QLocale::c().toLongLong(normalised, &ok))
                                   : QLocale::c().toDouble(normalised, &ok);
    if (!ok)
        return std::nullopt;
    return number;
}

double NumberField::stepFrom(double number) const {
    if (integer_)
        return 1.0;
    if (number == 0.0 || !std::isfinite(number))
        return kStepFromZero;
    return powerOfTenBelow(std::fabs(number)) / 10.0;
}

} // namespace airtrap
