// MPL outline: a scan of each line's first character, the controller's own label rule.
#include "mpl_outline.h"

#include "drive_core/pmc960/pmc960_program.h"

#include <QHash>
#include <QObject>
#include <QStringList>

namespace editor {

namespace {
bool isBlank(QChar c) {
    return c == QLatin1Char(' ') || c == QLatin1Char('\t');
}
} // namespace

Outline mplOutline(const QString& programText) {
    Outline out;
    QHash<QChar, int> first; // label -> 0-based line of its first @-line
    const QStringList lines = programLines(programText);
    for (qsizetype n = 0; n < lines.size(); ++n) {
        QString line = lines[n];
        if (line.endsWith(QLatin1Char('\r'))) line.chop(1);
        qsizetype i = 0;
        while (i < line.size() && isBlank(line.at(i))) ++i;
        if (i >= line.size() || line.at(i) != QLatin1Char('@')) continue;
        ++i;
        while (i < line.size() && isBlank(line.at(i))) ++i;
        if (i >= line.size()) continue;
        const QChar label = line.at(i);
        if (label == QLatin1Char('.') || label.unicode() > 0x7F ||
            !drive_core::pmc960::Pmc960Program::validLabel(char(label.unicode())))
            continue;
        OutlineEntry entry;
        entry.line = int(n);
        entry.name = QString(label);
        entry.detail = line.mid(i + 1).replace(QLatin1Char('_'), QLatin1Char(' ')).simplified();
        if (const auto earlier = first.constFind(label); earlier != first.constEnd()) {
            const QString never = QObject::tr("never reached: the label search stops at @%1 on line %2")
                                      .arg(label)
                                      .arg(*earlier + 1);
            entry.detail = entry.detail.isEmpty() ? never : never + QStringLiteral(" \u2014 ") + entry.detail;
        } else {
            first.insert(label, int(n));
        }
        out.push_back(std::move(entry));
    }
    return out;
}

} // namespace editor
