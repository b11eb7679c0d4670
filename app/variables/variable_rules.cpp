// VariableRules: the generic parts, and the family table.
#include "variable_rules.h"

#include "families/bds5/bds5_variable_rules.h"
#include "families/pmc960/pmc960_variable_rules.h"
#include "families/sc750/sc750_variable_rules.h"

#include <cmath>

namespace app {

namespace cat = drive_core::catalog;

std::unique_ptr<VariableRules> VariableRules::make(drive_core::DriveFamily family) {
    switch (family) {
    case drive_core::DriveFamily::Bds5: return std::make_unique<Bds5VariableRules>();
    case drive_core::DriveFamily::Sc750: return std::make_unique<Sc750VariableRules>();
    case drive_core::DriveFamily::Pmc960: return std::make_unique<Pmc960VariableRules>();
    }
    return std::make_unique<Bds5VariableRules>();
}

QString VariableRules::text(std::string_view view) {
    return QString::fromLatin1(view.data(), qsizetype(view.size()));
}

QString VariableRules::groupOf(const cat::Parameter& p) const {
    return text(p.group);
}

QString VariableRules::limitsText(const QString&, const cat::Parameter& p, const Context&) const {
    if (p.type == cat::ValueType::Switch) return QStringLiteral("OFF/ON");
    if (!p.ranged) return QStringLiteral("\u2014");
    return QStringLiteral("%1 \u2026 %2").arg(QString::number(p.minimum, 'g', 10), QString::number(p.maximum, 'g', 10));
}

bool VariableRules::editable(const QString&, const cat::Parameter& p) const {
    return p.writable != cat::Writable::Never && p.writable != cat::Writable::Factory;
}

QString VariableRules::displayValue(const cat::Parameter&, const QString& printed) const {
    return printed;
}

QStringList VariableRules::unreadable(const QStringList& names, const serialport::LineAnswer& answer) const {
    return names.size() == 1 && !answer.ok() ? names : QStringList();
}

std::optional<QString> VariableRules::schemaProblem(const QString& name, const cat::Parameter& p, const QString& typed) {
    if (p.writable == cat::Writable::Never) return tr("%1 is read only.").arg(name);
    if (p.writable == cat::Writable::Factory) return tr("%1 is set at the factory.").arg(name);
    const QString t = typed.trimmed();
    if (p.type == cat::ValueType::Text) {
        if (t.size() < 2 || !t.startsWith(QLatin1Char('"')) || !t.endsWith(QLatin1Char('"')))
            return tr("%1 takes a string in double quotes.").arg(name);
        return std::nullopt;
    }
    bool ok = false;
    const double value = t.toDouble(&ok);
    if (!ok) return tr("%1 takes a number, not \"%2\".").arg(name, t);
    if (p.type == cat::ValueType::Integer && value != std::floor(value))
        return tr("%1 is an integer: %2 has a fraction.").arg(name, t);
    if (p.ranged && (value < p.minimum || value > p.maximum))
        return tr("%1 must lie within %2 \u2013 %3.")
            .arg(name, QString::number(p.minimum, 'g', 10), QString::number(p.maximum, 'g', 10));
    return std::nullopt;
}

} // namespace app
