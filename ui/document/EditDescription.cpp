#include "document/EditDescription.h"

#include "scene/ParameterCodec.h"

#include <QCoreApplication>

namespace airtrap {

QString EditDescription::ofParameter(const QString& owner, const ParameterDeclaration& declaration,
                                     const ParameterValue& value) {
    return QCoreApplication::translate("EditDescription", "Set %1 %2 to %3")
        .arg(owner, labelInSentence(declaration.label), valueText(declaration, value));
}

QString EditDescription::labelInSentence(const std::string& label) {
    // Labels are capitalised for the panel ("Density"); mid-sentence they read in lower case,
    // except an acronym ("SPH kernel"), whose second letter is a capital too.
    QString text = QString::fromStdString(label);
    if (text.size() >= 2 && text[0].isUpper() && text[1].isLower())
        text[0] = text[0].toLower();
    return text;
}

QString EditDescription::valueText(const ParameterDeclaration& declaration,
                                   const ParameterValue& value) {
    if (const auto* flag = std::get_if<bool>(&value))
        return *flag ? QCoreApplication::translate("EditDescription", "on")
                     : QCoreApplication::translate("EditDescription", "off");
    if (const auto* text = std::get_if<std::string>(&value))
        return declaration.kind == ParameterKind::Choice
                   ? QString::fromStdString(*text)
                   : QStringLiteral("“%1”").arg(QString::fromStdString(*text));
    const QString number = QString::fromStdString(ParameterCodec::formatValue(value));
    return declaration.unit.empty()
               ? number
               : QStringLiteral("%1 %2").arg(number, QString::fromStdString(declaration.unit));
}

} // namespace airtrap
