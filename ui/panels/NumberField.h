#pragma once
// A spin box for one number of a parameter. Unlike QDoubleSpinBox's defaults it neither clamps
// nor rounds: it accepts any number the user types, so that an out-of-range value reaches
// SceneDocument::editParameter and the user reads the declaration's reason instead of watching
// the field silently change their number. It prints the shortest text that reads back exactly.
#include <QDoubleSpinBox>
#include <optional>

namespace airtrap {

class NumberField : public QDoubleSpinBox {
    Q_OBJECT

public:
    //! Whole numbers only when `integer` (Int parameters), any decimal number otherwise.
    explicit NumberField(bool integer, QWidget* parent = nullptr);

    //! Shows the document's `number` without emitting committed().
    void setNumber(double number);
    //! The number last given to setNumber(), i.e. the document's value.
    double number() const { return shown_; }

    //! Steps by 1 for integers, else by a tenth of the number's power of ten (0.02 → 0.001), and
    //! commits at once: each arrow click is one edit.
    void stepBy(int steps) override;
    //! Acceptable for a number, Intermediate for a partly typed one, Invalid for other text.
    QValidator::State validate(QString& input, int& position) const override;
    //! Puts back the document's number when the text is not a number.
    void fixup(QString& input) const override;
    //! The shortest text that reads back as `value`.
    QString textFromValue(double value) const override;
    //! The typed number, or the document's when the text is not a number.
    double valueFromText(const QString& text) const override;

Q_SIGNALS:
    //! The user entered `number` (Enter, leaving the field, or a step arrow) and it differs from
    //! the document's.
    void committed(double number);

protected:
    StepEnabled stepEnabled() const override;

private:
    void commitTypedText();
    std::optional<double> parsed(const QString& text) const;
    double stepFrom(double number) const;

    bool integer_;
    double shown_ = 0.0;
};

} // namespace airtrap
