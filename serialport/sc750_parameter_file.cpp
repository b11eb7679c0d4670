// Sc750ParameterFile: the PARAMS block, read and written (format in the header).
#include "sc750_parameter_file.h"

#include "drive_core/catalog/sc750_catalog.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <cmath>

namespace serialport {

namespace {
QString tr(const char* text) {
    return QCoreApplication::translate("serialport::Sc750ParameterFile", text);
}

// REM or ' begins a comment (L1222).
bool isComment(const QString& upperWord) {
    return upperWord.startsWith(QLatin1Char('\'')) || upperWord == QLatin1String("REM") ||
           upperWord.startsWith(QLatin1String("REM "));
}
} // namespace

Sc750ParameterFile Sc750ParameterFile::parse(const QString& text) {
    // NAME = number, then nothing but an optional ' comment.
    static const QRegularExpression kAssignment(
        QStringLiteral("^\\s*([A-Za-z][A-Za-z0-9._]*)\\s*=\\s*([-+]?[0-9.]+(?:[Ee][-+]?[0-9]+)?)\\s*(?:'.*)?$"));
    static const QRegularExpression kLineEnd(QStringLiteral("\r\n|\r|\n"));
    Sc750ParameterFile out;
    bool inBlock = false;
    const QStringList lines = text.split(kLineEnd);
    for (int i = 0; i < lines.size(); ++i) {
        const QString& line = lines[i];
        const QString word = line.simplified().toUpper();
        if (!inBlock) {
            inBlock = out.m_hasBlock = word.startsWith(QLatin1String("PARAMS START"));
            continue;
        }
        if (word.startsWith(QLatin1String("PARAMS END"))) break;
        if (word.isEmpty() || isComment(word)) continue;
        const auto m = kAssignment.match(line);
        bool number = false;
        if (m.hasMatch()) m.captured(2).toDouble(&number);
        if (!number) {
            out.m_problems.append({i + 1, line, tr("not an assignment (NAME = number)")});
            continue;
        }
        out.m_assignments.append({i + 1, m.captured(1).toUpper(), m.captured(2)});
    }
    return out;
}

// As Motion Dialogue writes the PARAMS block (L2505-2525): an integer parameter plain ("ILC = 59"), a real
// one with six decimals ("SIX.THRESH = 3147.836538", "KVI = 5.000000").
QString Sc750ParameterFile::formatValue(const std::string& name, double value) {
    namespace catalog = drive_core::catalog::sc750;
    const catalog::VariableInfo* info = catalog::findVariable(name);
    if (info && info->type == catalog::ValueType::Integer) return QString::number(std::llround(value));
    return QString::number(value, 'f', 6);
}

QString Sc750ParameterFile::block(const QList<QPair<QString, QString>>& values) {
    QStringList lines{QStringLiteral("PARAMS START")};
    for (const auto& [name, value] : values) lines << QStringLiteral("%1 = %2").arg(name, value.trimmed());
    lines << QStringLiteral("PARAMS END");
    return lines.join(QLatin1Char('\n'));
}

QString Sc750ParameterFile::withBlock(const QString& text, const QString& block) {
    static const QRegularExpression existing(
        QStringLiteral("^[ \\t]*PARAMS[ \\t]+START\\b.*?^[ \\t]*PARAMS[ \\t]+END[^\\n]*"),
        QRegularExpression::CaseInsensitiveOption | QRegularExpression::MultilineOption |
            QRegularExpression::DotMatchesEverythingOption);
    const QRegularExpressionMatch match = existing.match(text);
    if (match.hasMatch()) return QString(text).replace(match.capturedStart(), match.capturedLength(), block);
    return QStringLiteral("'-----Parameter Values Header-----\n") + block + QStringLiteral("\n\n") + text;
}

QString Sc750ParameterFile::toText(const QStringList& comments, const QList<QPair<QString, QString>>& values) {
    QString text;
    for (const QString& c : comments) text += QStringLiteral("' ") + c + QLatin1Char('\n');
    return text + block(values) + QLatin1Char('\n');
}

} // namespace serialport
