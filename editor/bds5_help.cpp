// BDS5 help topics and their catalog entries as HTML (the popup under F1; B2's reference browser takes the
// same topic names through ProgramEditor::helpRequested).
#include "bds5_help.h"

#include "parameter_help.h"

#include "bds5_line_styler.h"

#include "drive_core/catalog/bds5_catalog.h"

#include <QStringList>

#include <string>

namespace editor {

namespace cat = drive_core::catalog::bds5;

namespace {

bool isWordChar(QChar c) {
    return c.isLetterOrNumber() || c == QLatin1Char('_');
}
bool isBlank(QChar c) {
    return c == QLatin1Char(' ') || c == QLatin1Char('\t');
}
bool isNumber(const QString& word) {
    bool ok = false;
    word.toInt(&ok);
    return ok && !word.isEmpty() && word.front().isDigit();
}

// The blank-delimited entry that ends before `from` (backwards) or starts after `from` (forwards).
QString entryBefore(const QString& line, qsizetype from) {
    qsizetype end = from;
    while (end > 0 && isBlank(line[end - 1])) --end;
    qsizetype start = end;
    while (start > 0 && !isBlank(line[start - 1])) --start;
    return line.mid(start, end - start).toUpper();
}
QString entryAfter(const QString& line, qsizetype from) {
    qsizetype start = from;
    while (start < line.size() && isBlank(line[start])) ++start;
    qsizetype end = start;
    while (end < line.size() && !isBlank(line[end])) ++end;
    return line.mid(start, end - start).toUpper();
}

QString esc(std::string_view text) {
    return QString::fromUtf8(text.data(), qsizetype(text.size())).toHtmlEscaped();
}

QString muted(const QString& html) {
    return QStringLiteral("<span style=\"color:#6e7781\">%1</span>").arg(html);
}

QString modesText(unsigned modes) {
    QStringList parts;
    if (modes & cat::kInteractive) parts << QStringLiteral("interactive");
    if (modes & cat::kMonitor) parts << QStringLiteral("monitor");
    if (modes & cat::kProgram) parts << QStringLiteral("program");
    if (modes & cat::kEditor) parts << QStringLiteral("editor");
    return parts.join(QStringLiteral(", "));
}

QString commandHtml(const cat::CommandInfo& c) {
    QString html = QStringLiteral("<p style=\"margin:0\"><b>%1</b> &nbsp;%2</p>")
                       .arg(esc(c.name), muted(esc(c.longName) + QStringLiteral(" &middot; command")));
    html += QStringLiteral("<p style=\"margin:4px 0\"><code>%1</code></p>").arg(esc(c.syntax));
    html += QStringLiteral("<p style=\"margin:4px 0\">%1</p>").arg(esc(c.description));
    QString facts = QStringLiteral("Modes: %1").arg(modesText(c.modes));
    if (c.idling) facts += QStringLiteral(" &middot; idling");
    if (c.version3) facts += QStringLiteral(" &middot; firmware v3");
    facts += QStringLiteral(" &middot; Manual %1").arg(esc(c.manualLines));
    return html + QStringLiteral("<p style=\"margin:0\">%1</p>").arg(muted(facts));
}


QString conditionHtml(const QString& word) {
    static const QStringList kWords{"GT", "GE", "LT", "LE", "EQ", "NE"};
    static const QStringList kMeaning{
        "greater than", "greater than or equal to", "less than", "less than or equal to", "equal to", "not equal to"};
    const qsizetype i = kWords.indexOf(word);
    if (i < 0) return {};
    return QStringLiteral("<p style=\"margin:0\"><b>%1</b> &nbsp;%2</p><p style=\"margin:4px 0\">%3: "
                          "<code>&lt;expr&gt; %1 &lt;expr&gt;</code> in ?, TIL, IF and ELIF. Use GT GE LT LE EQ NE, "
                          "never = &gt; &lt;.</p><p style=\"margin:0\">%4</p>")
        .arg(word, muted(QStringLiteral("condition")), kMeaning[i], muted(QStringLiteral("Manual L3823-3835")));
}

} // namespace

QString bds5TopicAt(const QString& line, int column) {
    const QByteArray utf8 = line.left(column).toUtf8();
    const QByteArray styles = styleBds5Line(line.toUtf8());
    const qsizetype byte = utf8.size();
    // In a comment or a string there is nothing to look up (the byte before counts when at the end).
    for (const qsizetype b : {byte, byte - 1})
        if (b >= 0 && b < styles.size() && (styles[b] == Bds5Comment || styles[b] == Bds5String)) return {};

    qsizetype start = qMin<qsizetype>(column, line.size());
    qsizetype end = start;
    while (start > 0 && isWordChar(line[start - 1])) --start;
    while (end < line.size() && isWordChar(line[end])) ++end;
    if (start == end) { // on punctuation: ? is the quick IF, a lone $ a label
        const QChar c = column < line.size() ? line[column] : (column > 0 ? line[column - 1] : QChar());
        if (c == QLatin1Char('?')) return QStringLiteral("?");
        return {};
    }
    const QString word = line.mid(start, end - start).toUpper();
    if (end < line.size() && line[end] == QLatin1Char('$')) return QStringLiteral("$");
    if (start > 0 && (line[start - 1] == QLatin1Char('<') || line[start - 1] == QLatin1Char('>')) &&
        word == QLatin1String("BDS"))
        return line[start - 1] + word;
    if (isNumber(word)) {
        if (entryBefore(line, start) == QLatin1String("ERR")) return QStringLiteral("ERR ") + word;
        return {};
    }
    if (word == QLatin1String("ERR")) {
        const QString next = entryAfter(line, end);
        if (isNumber(next)) return QStringLiteral("ERR ") + next;
    }
    return word;
}

QString bds5HelpHtml(const QString& topic) {
    QString t = topic.trimmed().toUpper();
    if (t.startsWith(QLatin1String("ERR ")) || isNumber(t)) {
        const int code = t.section(QLatin1Char(' '), -1).toInt();
        const auto* e = drive_core::catalog::findError(drive_core::DriveFamily::Bds5, code);
        return e ? errorHelpHtml(*e, QStringLiteral("ERR ")) : QString();
    }
    if (const QString condition = conditionHtml(t); !condition.isEmpty()) return condition;
    const std::string name = t.toStdString();
    QStringList sections;
    if (const cat::CommandInfo* c = cat::findCommand(name)) sections << commandHtml(*c);
    if (const auto v = cat::findVariable(name))
        if (const auto* p = parameterNamed(drive_core::DriveFamily::Bds5, v->info->name))
            sections << parameterHelpHtml(*p);
    return sections.join(QStringLiteral("<hr>"));
}

} // namespace editor
