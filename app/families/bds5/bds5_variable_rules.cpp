// Bds5VariableRules: P, NAME value, and the App. E checks.
#include "bds5_variable_rules.h"

#include "variables/variable_validator.h"

#include <QRegularExpression>

namespace app {

namespace cat = drive_core::catalog;

namespace {
// The user units (Table 6.2): they scale every limit shown.
const QStringList& unitNames() {
    static const QStringList names{"PNUM", "PDEN", "VNUM", "VDEN",  "ANUM",  "ADEN",
                                   "INUM", "IDEN", "PXNUM", "PXDEN", "VXNUM", "VXDEN"};
    return names;
}
} // namespace

QStringList Bds5VariableRules::groupOrder() const {
    return {"Position", "Velocity",      "Current", "Loop gains", "Limits", "Units",
            "Inputs and outputs", "Switches", "Communication", "Timers", "Record", "User variables"};
}

QString Bds5VariableRules::limitsText(const QString& name, const cat::Parameter&, const Context& c) const {
    namespace b5 = cat::bds5;
    const auto ref = b5::findVariable(name.toUpper().toStdString());
    if (!ref) return {};
    const b5::VariableInfo& info = *ref->info;
    if (info.limits == b5::LimitClass::None) return QStringLiteral("\u2014");
    if (info.limits == b5::LimitClass::Switch) return QStringLiteral("OFF/ON");
    if (info.limits == b5::LimitClass::Long) return tr("any (32-bit)"); // whole 32-bit ranges say little as numbers
    if (const auto user = VariableValidator::userLimits(info, c)) {
        if (info.limits == b5::LimitClass::LongPositive && info.unitClass == b5::UnitClass::None)
            return tr("\u2265 0 (32-bit)");
        return QStringLiteral("%1 \u2026 %2").arg(QString::number(user->first, 'g', 7), QString::number(user->second, 'g', 7));
    }
    return tr("%1 \u2026 %2 (basic units)").arg(b5::minimumOf(info)).arg(b5::maximumOf(info));
}

QString Bds5VariableRules::displayValue(const cat::Parameter& p, const QString& printed) const {
    if (p.type != cat::ValueType::Switch || printed.isEmpty()) return printed;
    return printed == QLatin1String("0") ? QStringLiteral("OFF") : QStringLiteral("ON");
}

VariableRules::Verdict Bds5VariableRules::check(const QString& name, const QString& text, const Context& c) const {
    const VariableValidator::Verdict v = VariableValidator::check(name, text, c);
    Verdict verdict{v.ok, {}, v.message};
    if (v.ok) verdict.lines << v.instruction;
    return verdict;
}

bool Bds5VariableRules::scalesLimits(const QString& name) const {
    return unitNames().contains(name.toUpper());
}

// The units until they are known; ACTIVE always, as it decides what may be written.
QStringList Bds5VariableRules::alsoRead(const Context& c) const {
    QStringList names;
    for (const QString& name : unitNames())
        if (!c.valueOf(name)) names << name;
    return names << QStringLiteral("ACTIVE");
}

QString Bds5VariableRules::readLine(const QStringList& names) const {
    return QStringLiteral("P ") + names.join(QLatin1Char(' '));
}

QStringList Bds5VariableRules::values(const QStringList& names, const serialport::LineAnswer& answer) const {
    if (!answer.ok() || answer.garbled) return {};
    static const QRegularExpression kBlanks(QStringLiteral("\\s+"));
    const QStringList words = answer.lines.join(QLatin1Char(' ')).split(kBlanks, Qt::SkipEmptyParts);
    return words.size() == names.size() ? words : QStringList(); // else a program printed meanwhile
}

// One name the drive cannot print spoils the whole P: its ERR line names the entry ("ERR 80 'XYZ' ...").
QStringList Bds5VariableRules::unreadable(const QStringList& names, const serialport::LineAnswer& answer) const {
    static const QRegularExpression kEntry(QStringLiteral("^ERR \\d+ '([^']*)'"));
    QStringList out;
    for (const QString& line : answer.lines)
        if (const auto m = kEntry.match(line); m.hasMatch() && names.contains(m.captured(1).toUpper()))
            out << m.captured(1).toUpper();
    return out;
}

// Motion Link's variable file: "NAME value" a line, as the drive's P prints it and VARIABLES > Send takes it.
VariableRules::FileText Bds5VariableRules::fileText(const QList<QPair<QString, QString>>& values) const {
    FileText file;
    for (const auto& [name, value] : values) {
        file.text += name.toUpper() + QLatin1Char(' ') + value + QLatin1Char('\n');
        ++file.count;
    }
    return file;
}

QString Bds5VariableRules::hint() const {
    return tr("Double-click a value to change it; it is checked against Appendix E first.");
}

} // namespace app
