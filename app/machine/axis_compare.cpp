// Axis compare: variables by name, program lines by alignment.
#include "axis_compare.h"

#include "serialport/bds5_variable_file.h"
#include "serialport/pmc960_parameter_file.h"
#include "serialport/sc750_parameter_file.h"

#include <algorithm>
#include <vector>

namespace app::machine {

using drive_core::DriveFamily;

namespace {

// The PMC-960 parameter a setting line sets: the longest name it starts with ("TGP16" -> TGP, 16).
std::optional<NamedValue> pmc960Setting(const QString& command, int line) {
    QString best;
    for (const serialport::Pmc960Parameter* p : serialport::Pmc960ParameterFile::backedUp()) {
        const QString name = serialport::parameterName(*p);
        if (command.startsWith(name, Qt::CaseInsensitive) && name.size() > best.size()) best = name;
    }
    if (best.isEmpty()) return std::nullopt; // SW0, SW1
    return NamedValue{best, command.mid(best.size()), line};
}

bool sameValue(const QString& a, const QString& b) {
    if (a.trimmed().compare(b.trimmed(), Qt::CaseInsensitive) == 0) return true;
    bool na = false, nb = false;
    const double x = a.toDouble(&na), y = b.toDouble(&nb);
    return na && nb && x == y;
}

QString withoutTrailingBlanks(const QString& line) {
    qsizetype n = line.size();
    while (n > 0 && line[n - 1].isSpace()) --n;
    return line.left(n);
}

} // namespace

QList<NamedValue> namedValues(DriveFamily family, const QString& fileText) {
    QList<NamedValue> values;
    switch (family) {
    case DriveFamily::Bds5: {
        const auto file = serialport::Bds5VariableFile::parse(fileText);
        for (const auto& a : file.assignments()) values.append({a.name, a.value, a.sourceLine});
        break;
    }
    case DriveFamily::Sc750: {
        const auto file = serialport::Sc750ParameterFile::parse(fileText);
        for (const auto& a : file.assignments()) values.append({a.name, a.value, a.sourceLine});
        break;
    }
    case DriveFamily::Pmc960: {
        const auto file = serialport::Pmc960ParameterFile::parse(fileText);
        for (const auto& l : file.lines())
            if (auto v = pmc960Setting(l.command, l.sourceLine)) values.append(*v);
        break;
    }
    }
    return values;
}

QList<CompareRow> compareVariables(DriveFamily family, const QString& left, const QString& right) {
    const QList<NamedValue> l = namedValues(family, left), r = namedValues(family, right);
    const auto find = [](const QList<NamedValue>& in, const QString& name) -> const NamedValue* {
        for (auto it = in.crbegin(); it != in.crend(); ++it) // the last assignment wins, as on the drive
            if (it->name.compare(name, Qt::CaseInsensitive) == 0) return &*it;
        return nullptr;
    };
    QList<CompareRow> rows;
    QStringList seen;
    for (const NamedValue& v : l) {
        if (seen.contains(v.name, Qt::CaseInsensitive)) continue;
        seen << v.name;
        const NamedValue* lv = find(l, v.name);
        const NamedValue* rv = find(r, v.name);
        CompareRow row{CompareRow::Kind::Variable, v.name, lv->value, rv ? rv->value : QString(), lv->line,
                       rv ? rv->line : 0, !rv || !sameValue(lv->value, rv->value)};
        rows.append(row);
    }
    for (const NamedValue& v : r) {
        if (seen.contains(v.name, Qt::CaseInsensitive)) continue;
        seen << v.name;
        const NamedValue* rv = find(r, v.name);
        rows.append({CompareRow::Kind::Variable, v.name, QString(), rv->value, 0, rv->line, true});
    }
    return rows;
}

// Longest common subsequence of the lines, then one row per line of either side.
QList<CompareRow> compareProgram(const QStringList& leftLines, const QStringList& rightLines) {
    QStringList a, b;
    for (const QString& s : leftLines) a << withoutTrailingBlanks(s);
    for (const QString& s : rightLines) b << withoutTrailingBlanks(s);
    const std::size_t n = std::size_t(a.size()), m = std::size_t(b.size());
    std::vector<std::vector<int>> common(n + 1, std::vector<int>(m + 1, 0)); // common[i][j]: of a[i..], b[j..]
    for (std::size_t i = n; i-- > 0;)
        for (std::size_t j = m; j-- > 0;)
            common[i][j] = a[qsizetype(i)] == b[qsizetype(j)] ? common[i + 1][j + 1] + 1
                                                                : std::max(common[i + 1][j], common[i][j + 1]);
    QList<CompareRow> rows;
    std::size_t i = 0, j = 0;
    const auto row = [&](bool left, bool right) {
        CompareRow r;
        r.kind = CompareRow::Kind::ProgramLine;
        if (left) {
            r.left = a[qsizetype(i)];
            r.leftLine = int(++i);
            r.key = QString::number(r.leftLine);
        }
        if (right) {
            r.right = b[qsizetype(j)];
            r.rightLine = int(++j);
        }
        r.differs = !(left && right);
        rows.append(r);
    };
    while (i < n || j < m) {
        if (i < n && j < m && a[qsizetype(i)] == b[qsizetype(j)]) {
            row(true, true);
        } else if (i < n && j < m && common[i + 1][j + 1] == common[i][j]) { // a changed line: side by side
            row(true, true);
            rows.last().differs = true;
        } else if (j >= m || (i < n && common[i + 1][j] >= common[i][j + 1])) {
            row(true, false);
        } else {
            row(false, true);
        }
    }
    return rows;
}

QList<CompareRow> differences(const QList<CompareRow>& rows) {
    QList<CompareRow> out;
    std::copy_if(rows.begin(), rows.end(), std::back_inserter(out), [](const CompareRow& r) { return r.differs; });
    return out;
}

QString settingLine(DriveFamily family, const QString& name, const QString& value) {
    switch (family) {
    case DriveFamily::Bds5: return name + QLatin1Char(' ') + value;
    case DriveFamily::Sc750: return name + QLatin1Char('=') + value;
    case DriveFamily::Pmc960: return name + value;
    }
    return {};
}

QStringList settingLines(DriveFamily family, const QList<NamedValue>& values) {
    QStringList lines;
    for (const NamedValue& v : values) lines << settingLine(family, v.name, v.value);
    if (family == DriveFamily::Pmc960 && !lines.isEmpty()) {
        lines.prepend(QStringLiteral("SW1"));
        lines.append(QStringLiteral("SW0"));
    }
    return lines;
}

QStringList linkSettings(DriveFamily family) {
    if (family == DriveFamily::Bds5) return {QStringLiteral("ADDR"), QStringLiteral("BAUD"), QStringLiteral("ABAUD")};
    return {}; // the SC750's AXIS.ADDR is its DIP switch; the PMC-960's file leaves THB, THC, THI out already
}

QString withoutVariables(DriveFamily family, const QString& fileText, const QStringList& names) {
    QStringList lines = fileText.split(QLatin1Char('\n'));
    const QList<NamedValue> values = namedValues(family, fileText);
    for (auto it = values.crbegin(); it != values.crend(); ++it)
        if (names.contains(it->name, Qt::CaseInsensitive)) lines.removeAt(it->line - 1);
    return lines.join(QLatin1Char('\n'));
}

QString withValue(DriveFamily family, const QString& fileText, const QString& name, const QString& value) {
    QStringList lines = fileText.split(QLatin1Char('\n'));
    const QList<NamedValue> values = namedValues(family, fileText);
    for (auto it = values.crbegin(); it != values.crend(); ++it) {
        if (it->name.compare(name, Qt::CaseInsensitive) != 0) continue;
        QString& line = lines[it->line - 1];
        const QString ending = line.endsWith(QLatin1Char('\r')) ? QStringLiteral("\r") : QString();
        line = (family == DriveFamily::Sc750 ? name + QStringLiteral(" = ") + value : settingLine(family, name, value)) +
               ending;
        return lines.join(QLatin1Char('\n'));
    }
    const QString added = family == DriveFamily::Sc750 ? name + QStringLiteral(" = ") + value
                                                        : settingLine(family, name, value);
    if (family == DriveFamily::Sc750) { // inside the PARAMS block
        const qsizetype end = lines.indexOf(QStringLiteral("PARAMS END"));
        if (end >= 0) {
            lines.insert(end, added);
            return lines.join(QLatin1Char('\n'));
        }
    }
    if (family == DriveFamily::Pmc960) { // before the closing SW0
        const qsizetype end = lines.lastIndexOf(QStringLiteral("SW0"));
        if (end >= 0) {
            lines.insert(end, added);
            return lines.join(QLatin1Char('\n'));
        }
    }
    if (!lines.isEmpty() && lines.last().isEmpty()) lines.insert(lines.size() - 1, added);
    else lines.append(added);
    return lines.join(QLatin1Char('\n'));
}

} // namespace app::machine
