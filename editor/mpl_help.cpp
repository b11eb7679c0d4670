// MPL F1 help: the MPL line styler finds where commands start; the catalog supplies the words.
#include "mpl_help.h"

#include "parameter_help.h"

#include "drive_core/catalog/pmc960_catalog.h"
#include "mpl_line_styler.h"

#include <QRegularExpression>

#include <cctype>

namespace editor {

namespace cat = drive_core::catalog::pmc960;

namespace {
QString text(std::string_view s) {
    return QString::fromUtf8(s.data(), qsizetype(s.size()));
}
} // namespace

QString mplTopicAt(const QString& line, int column) {
    static const QRegularExpression kError(QStringLiteral("#([0-9A-Fa-f]{2})"));
    for (auto it = kError.globalMatch(line); it.hasNext();) {
        const auto m = it.next();
        if (column >= m.capturedStart() && column < m.capturedEnd())
            return QStringLiteral("#") + m.captured(1).toUpper();
    }
    if (line.startsWith(QLatin1Char('@'))) return QStringLiteral("@");
    const QByteArray bytes = line.toLatin1();
    const QByteArray styles = styleMplLine(bytes);
    // The command the cursor belongs to: the last run of command letters at or before the cursor.
    int end = std::min(column, int(bytes.size()) - 1);
    while (end >= 0 && styles[end] != MplCommand) --end;
    if (end < 0) return {};
    int start = end;
    while (start > 0 && styles[start - 1] == MplCommand) --start;
    // Letters right after a sign, number or label continue the command before (TG registers, L's X/Y/Z).
    if (start > 0 &&
        (styles[start - 1] == MplSign || styles[start - 1] == MplNumber || styles[start - 1] == MplLabel)) {
        const QString before = mplTopicAt(line, start - 1);
        const QString gain = QStringLiteral("TG") + QChar::fromLatin1(char(std::toupper(bytes[start])));
        return before.startsWith(QLatin1String("TG")) && cat::findCommand(gain.toStdString()) ? gain : before;
    }
    QString word = QString::fromLatin1(bytes.mid(start, end - start + 1)).toUpper();
    // TGP++V5--: a later register letter belongs to TG; LBX20: X is L's counter.
    while (!word.isEmpty() && !cat::findCommand(word.toStdString())) word.chop(1);
    if (word.isEmpty() && start > 0) return mplTopicAt(line, start - 1);
    return word;
}

QString mplHelpHtml(const QString& topic) {
    if (topic.startsWith(QLatin1Char('#'))) {
        const auto* e = drive_core::catalog::findError(drive_core::DriveFamily::Pmc960, topic.mid(1).toInt(nullptr, 16));
        return e ? errorHelpHtml(*e) : QString();
    }
    const auto* c = cat::findCommand(topic.toStdString());
    if (!c) return {};
    QString html = QStringLiteral("<b>%1</b> — %2<br><code>%3</code><p>%4</p>")
                       .arg(text(c->name).toHtmlEscaped(), text(c->longName).toHtmlEscaped(),
                            text(c->syntax).toHtmlEscaped(), text(c->description).toHtmlEscaped());
    if (const auto* p = parameterNamed(drive_core::DriveFamily::Pmc960, text(c->name).toStdString()))
        html += QStringLiteral("<hr>") + parameterHelpHtml(*p);
    return html + QStringLiteral("<p><i>Manual %1</i></p>").arg(text(c->manualLines));
}

} // namespace editor
