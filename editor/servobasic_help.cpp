// ServoBASIC help: word finding, completion names and the catalog's entries as HTML.
#include "servobasic_help.h"

#include "parameter_help.h"

#include "drive_core/catalog/sc750_catalog.h"

namespace editor {

namespace catalog = drive_core::catalog::sc750;

namespace {
QString str(std::string_view text) {
    return QString::fromLatin1(text.data(), qsizetype(text.size()));
}
QString typeName(catalog::ValueType type) {
    switch (type) {
    case catalog::ValueType::Integer: return QStringLiteral("Integer");
    case catalog::ValueType::Float: return QStringLiteral("Float");
    case catalog::ValueType::String: return QStringLiteral("String");
    }
    return {};
}
} // namespace

bool isServoBasicWordChar(QChar c) {
    return c.isLetterOrNumber() || c == QLatin1Char('.') || c == QLatin1Char('_') || c == QLatin1Char('$');
}

QString servoBasicTopicAt(const QString& text, int column) {
    int start = qMin(column, int(text.size()));
    if (start > 0 && (start == text.size() || !isServoBasicWordChar(text[start]))) --start; // just after a word
    if (start < 0 || start >= text.size() || !isServoBasicWordChar(text[start])) return {};
    while (start > 0 && isServoBasicWordChar(text[start - 1])) --start;
    int end = start;
    while (end < text.size() && isServoBasicWordChar(text[end])) ++end;
    return text.mid(start, end - start);
}

QStringList servoBasicCompletions(const QString& prefix) {
    // Every catalog name, sorted: statements, functions, predefined variables and parameters.
    static const QStringList names = [] {
        QStringList all;
        for (const auto& s : catalog::statements()) all << str(s.name);
        for (const auto& f : catalog::functions()) all << str(f.name);
        for (const auto& v : catalog::variables()) all << str(v.name);
        all.sort();
        all.removeDuplicates();
        return all;
    }();
    QStringList matches;
    for (const QString& name : names)
        if (name.startsWith(prefix, Qt::CaseInsensitive) && name.compare(prefix, Qt::CaseInsensitive) != 0)
            matches << name;
    return matches;
}

QString servoBasicHelpHtml(const QString& word) {
    const std::string name = word.toUpper().toStdString();
    if (const auto* s = catalog::findStatement(name))
        return QStringLiteral(
                   "<b>%1</b> (Statement)<br><b>Syntax:</b> <code>%2</code><br>%3<br><small>Manual %4</small>")
            .arg(str(s->name), str(s->syntax).toHtmlEscaped(), str(s->description).toHtmlEscaped(),
                 str(s->manualLines));
    if (const auto* f = catalog::findFunction(name))
        return QStringLiteral(
                   "<b>%1</b> (Function, %2)<br><b>Syntax:</b> <code>%3</code><br>%4<br><small>Manual %5</small>")
            .arg(str(f->name), typeName(f->result), str(f->syntax).toHtmlEscaped(), str(f->description).toHtmlEscaped(),
                 str(f->manualLines));
    if (const auto* v = catalog::findVariable(name))
        if (const auto* p = parameterNamed(drive_core::DriveFamily::Sc750, v->name)) return parameterHelpHtml(*p);
    return {};
}

} // namespace editor
