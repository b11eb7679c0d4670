// Sc750VariableRules: G reads, P writes, the catalog's checks.
#include "sc750_variable_rules.h"

#include "sc750_variable_groups.h"

#include "drive_core/catalog/sc750_catalog.h"
#include "serialport/sc750_parameter_file.h"

namespace app {

namespace {
const drive_core::catalog::sc750::VariableInfo* infoOf(const QString& name) {
    return drive_core::catalog::sc750::findVariable(name.toUpper().toStdString());
}
} // namespace

QStringList Sc750VariableRules::groupOrder() const {
    return sc750VariableGroups();
}

QString Sc750VariableRules::groupOf(const drive_core::catalog::Parameter& p) const {
    const auto* info = infoOf(text(p.name));
    return info ? sc750VariableGroup(*info) : sc750VariableGroups().last();
}

QString Sc750VariableRules::limitsText(const QString& name, const drive_core::catalog::Parameter&, const Context&) const {
    const auto* info = infoOf(name);
    return info ? sc750RangeText(*info) : QString();
}

VariableRules::Verdict Sc750VariableRules::check(const QString& name, const QString& typed, const Context&) const {
    Verdict verdict;
    const auto* info = infoOf(name);
    if (!info) {
        verdict.message = tr("%1 is not a predefined SC750 variable.").arg(name);
        return verdict;
    }
    if (const std::optional<QString> refusal = sc750CheckValue(*info, typed)) {
        verdict.message = *refusal;
        return verdict;
    }
    verdict.ok = true;
    verdict.lines << QStringLiteral("%1=%2").arg(name.toUpper(), typed.trimmed());
    return verdict;
}

// G answers "NAME=value" (the session may have taken the name off already).
QStringList Sc750VariableRules::values(const QStringList& names, const serialport::LineAnswer& answer) const {
    if (!answer.ok() || names.size() != 1 || answer.lines.isEmpty()) return {};
    const QString& line = answer.lines.first();
    return {line.mid(line.indexOf(QLatin1Char('=')) + 1)};
}

QString Sc750VariableRules::hint() const {
    return tr("Double-click a value to change it; the SC750 takes changes while no program executes.");
}

// A .PRM holds the set-up parameters only (the PARAMS block, L943-L975): a run-time variable cannot be in it.
VariableRules::FileText Sc750VariableRules::fileText(const QList<QPair<QString, QString>>& values) const {
    namespace cat = drive_core::catalog::sc750;
    QList<QPair<QString, QString>> parameters;
    for (const auto& [name, value] : values) {
        const std::string upper = name.toUpper().toStdString();
        const cat::VariableInfo* v = cat::findVariable(upper);
        if (!v || v->access != cat::Access::Parameter) continue;
        bool number = false;
        const double x = value.toDouble(&number);
        parameters.append({name.toUpper(), number ? serialport::Sc750ParameterFile::formatValue(upper, x) : value});
    }
    return {parameters.isEmpty() ? QString() : serialport::Sc750ParameterFile::block(parameters) + QLatin1Char('\n'),
            int(parameters.size())};
}

} // namespace app
