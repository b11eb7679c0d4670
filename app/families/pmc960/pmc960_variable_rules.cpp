// Pmc960VariableRules: ? and ! displays, checked writes.
#include "pmc960_variable_rules.h"

#include "serialport/pmc960_parameter_file.h"
#include "serialport/pmc960_parameter_values.h"

#include <algorithm>

namespace app {

namespace {
using serialport::Pmc960Parameter;

const Pmc960Parameter* find(const QString& name) {
    for (const Pmc960Parameter& p : drive_core::catalog::pmc960::parameters())
        if (serialport::parameterName(p).compare(name, Qt::CaseInsensitive) == 0) return &p;
    return nullptr;
}

QString display(const QString& name, char kind) {
    const Pmc960Parameter* p = find(name);
    return p ? QString::fromLatin1(serialport::displayCommand(*p, kind)) : QString();
}
} // namespace

QString Pmc960VariableRules::limitsText(const QString& name, const drive_core::catalog::Parameter&, const Context&) const {
    const Pmc960Parameter* p = find(name);
    return p ? serialport::rangeText(*p) : QString();
}

bool Pmc960VariableRules::editable(const QString& name, const drive_core::catalog::Parameter&) const {
    const Pmc960Parameter* p = find(name);
    return p && !serialport::isReadOnlyFromHost(*p); // see there: what would cut the link off or start motion
}

VariableRules::Verdict Pmc960VariableRules::check(const QString& name, const QString& text, const Context&) const {
    Verdict verdict;
    const Pmc960Parameter* p = find(name);
    if (!p || serialport::isReadOnlyFromHost(*p)) {
        verdict.message = tr("%1 is read only in this table.").arg(name);
        return verdict;
    }
    const serialport::ParameterWrite write = serialport::parameterWrite(*p, text);
    if (!write.error.isEmpty()) {
        verdict.message = write.error;
        return verdict;
    }
    const QString command = QString::fromLatin1(write.command).trimmed();
    verdict.ok = true;
    verdict.lines = write.needsWriteEnable ? QStringList{QStringLiteral("SW1"), command, QStringLiteral("SW0")}
                                           : QStringList{command};
    return verdict;
}

QString Pmc960VariableRules::readLine(const QStringList& names) const {
    return display(names.value(0), '?');
}

QString Pmc960VariableRules::secondReadLine(const QString& name) const {
    return display(name, '!');
}

QStringList Pmc960VariableRules::values(const QStringList& names, const serialport::LineAnswer& answer) const {
    const Pmc960Parameter* p = names.size() == 1 ? find(names.first()) : nullptr;
    if (!p || !answer.ok()) return {};
    return {serialport::valueFromDisplay(*p, answer.lines.join(QLatin1Char(' ')))};
}

QString Pmc960VariableRules::hint() const {
    return tr("Double-click a stored value to change it; a T-table value is written between SW1 and SW0.");
}

// The parameter table as the lines that set it (Pmc960ParameterFile): the T-table parameters a backup holds,
// between SW1 and SW0, with their stored (?) values; the motion buffer and system registers are left out.
VariableRules::FileText Pmc960VariableRules::fileText(const QList<QPair<QString, QString>>& values) const {
    using serialport::Pmc960ParameterFile;
    const auto backedUp = Pmc960ParameterFile::backedUp();
    QStringList lines;
    for (const auto& [name, value] : values) {
        const Pmc960Parameter* p = find(name);
        if (!p || std::find(backedUp.begin(), backedUp.end(), p) == backedUp.end()) continue;
        if (const QString line = Pmc960ParameterFile::settingLine(*p, value); !line.isEmpty()) lines << line;
    }
    return {lines.isEmpty() ? QString() : Pmc960ParameterFile::toText({}, lines), int(lines.size())};
}

} // namespace app
