// Pmc960ParameterFile: the parameter table as MPL lines, read and written (format in the header).
#include "pmc960_parameter_file.h"

#include <QCoreApplication>
#include <QRegularExpression>

namespace serialport {

namespace {
QString tr(const char* text) {
    return QCoreApplication::translate("serialport::Pmc960ParameterFile", text);
}

// The catalog parameter whose name begins the line, the longest one ("SLF" before a shorter name).
const Pmc960Parameter* parameterOf(const QString& line) {
    const Pmc960Parameter* found = nullptr;
    for (const Pmc960Parameter& p : drive_core::catalog::pmc960::parameters()) {
        const QString name = parameterName(p);
        if (line.startsWith(name) && (!found || name.size() > parameterName(*found).size())) found = &p;
    }
    return found;
}
} // namespace

Pmc960ParameterFile Pmc960ParameterFile::parse(const QString& text) {
    Pmc960ParameterFile out;
    static const QRegularExpression kLineEnd(QStringLiteral("\r\n|\r|\n"));
    static const QRegularExpression kBlanks(QStringLiteral("[ \\t]")); // fillers at the prompt (L1412)
    const QStringList lines = text.split(kLineEnd);
    for (int i = 0; i < lines.size(); ++i) {
        const QString line = QString(lines[i]).remove(kBlanks).toUpper();
        if (line.isEmpty() || line.startsWith(QLatin1String("@."))) continue;
        const auto problem = [&](const QString& message) { out.m_problems.append({i + 1, lines[i], message}); };
        const Pmc960Parameter* p = parameterOf(line);
        if (!p) {
            problem(tr("not a parameter setting (<name><value>, as TGP16)"));
            continue;
        }
        const QString name = parameterName(*p);
        if (isReadOnlyFromHost(*p) && name != QLatin1String("SW")) {
            problem(
                tr("%1 is not sent: the host leaves it alone (it would cut the link off or start motion)").arg(name));
            continue;
        }
        QString value = line.mid(name.size());
        // SL<F|R><position>[<sign>]: the sign follows the number.
        if ((name == QLatin1String("SLF") || name == QLatin1String("SLR")) && !value.isEmpty() &&
            (value.endsWith(QLatin1Char('-')) || value.endsWith(QLatin1Char('+'))))
            value = (value.endsWith(QLatin1Char('-')) ? QStringLiteral("-") : QString()) + value.chopped(1);
        const ParameterWrite write = parameterWrite(*p, value);
        if (!write.error.isEmpty()) {
            problem(write.error);
            continue;
        }
        out.m_lines.append({i + 1, QString::fromLatin1(write.command).trimmed()});
    }
    return out;
}

std::vector<const Pmc960Parameter*> Pmc960ParameterFile::backedUp() {
    std::vector<const Pmc960Parameter*> list;
    for (const Pmc960Parameter& p : drive_core::catalog::pmc960::parameters())
        if (p.nonVolatile && !isReadOnlyFromHost(p)) list.push_back(&p);
    return list;
}

QString Pmc960ParameterFile::settingLine(const Pmc960Parameter& p, const QString& displayedValue) {
    if (displayedValue.trimmed().isEmpty()) return {};
    const ParameterWrite write = parameterWrite(p, displayedValue);
    return write.error.isEmpty() ? QString::fromLatin1(write.command).trimmed() : QString();
}

QString Pmc960ParameterFile::toText(const QStringList& comments, const QStringList& settingLines) {
    QString text;
    for (const QString& c : comments)
        text += QStringLiteral("@.") + QString(c).replace(QLatin1Char(' '), QLatin1Char('_')) + QLatin1Char('\n');
    text += QStringLiteral("SW1\n");
    for (const QString& l : settingLines) text += l + QLatin1Char('\n');
    text += QStringLiteral("SW0\n");
    return text;
}

} // namespace serialport
