// parameterHelpHtml, errorHelpHtml: one page layout for every family's parameters and errors.
#include "parameter_help.h"

#include <QLocale>
#include <QStringList>

namespace editor {

namespace {

namespace cat = drive_core::catalog;

QString esc(std::string_view text) {
    return QString::fromUtf8(text.data(), qsizetype(text.size())).toHtmlEscaped();
}

QString muted(const QString& html) {
    return QStringLiteral("<span style=\"color:#666\">%1</span>").arg(html);
}

// Up to 9 significant digits, without a trailing ".0": 0.087086, 16, -2147483648.
QString number(double value) {
    return QString::number(value, 'g', 10);
}

QString page(const QString& title, const QString& kind, const QStringList& facts, std::string_view words,
             std::string_view manualLines, const QString& extra = {}) {
    QString html = QStringLiteral("<p style=\"margin:0\"><b>%1</b> &nbsp;%2</p>").arg(title, muted(kind));
    if (!facts.isEmpty())
        html += QStringLiteral("<p style=\"margin:4px 0\">%1</p>").arg(facts.join(QStringLiteral(" &middot; ")));
    if (!words.empty()) html += QStringLiteral("<p style=\"margin:4px 0\">%1</p>").arg(esc(words));
    html += extra;
    return html + QStringLiteral("<p style=\"margin:0\">%1</p>").arg(muted(QStringLiteral("Manual %1").arg(esc(manualLines))));
}

} // namespace

QString parameterHelpHtml(const cat::Parameter& p) {
    QString title = p.firstIndex > 0 ? QStringLiteral("%1%2..%1%3").arg(esc(p.name)).arg(p.firstIndex).arg(p.lastIndex)
                                     : esc(p.name);
    if (p.extendedLastIndex > p.lastIndex) // v3: X251..X750 while EXTDX is on
        title += QStringLiteral(", %1%2..%1%3 with %4 on")
                     .arg(esc(p.name))
                     .arg(p.lastIndex + 1)
                     .arg(p.extendedLastIndex)
                     .arg(esc(p.extendedBy));
    QStringList facts;
    facts << esc(cat::typeName(p.type));
    if (!p.unit.empty()) facts << QStringLiteral("Units: %1").arg(esc(p.unit));
    if (p.ranged && p.type != cat::ValueType::Switch)
        facts << QStringLiteral("Range: %1 to %2").arg(number(p.minimum), number(p.maximum));
    facts << QStringLiteral("Write: %1").arg(esc(cat::writableText(p.writable)));
    if (p.powerUp)
        facts << QStringLiteral("%1: %2%3")
                     .arg(p.nonVolatile ? QStringLiteral("Factory value") : QStringLiteral("Power-up"))
                     .arg(number(*p.powerUp))
                     .arg(p.nonVolatile ? QStringLiteral(" (kept without power)") : QString());
    if (p.chosen) facts << QStringLiteral("<i>range and value chosen by ServoDesk: the manual gives none</i>");
    return page(title, esc(p.group), facts, p.description, p.manualLines);
}

const cat::Parameter* parameterNamed(drive_core::DriveFamily family, std::string_view name) {
    for (const cat::Parameter& p : cat::parameters(family))
        if (p.name == name) return &p;
    return nullptr;
}

QString errorHelpHtml(const cat::ErrorEntry& e, const QString& codePrefix) {
    const QString extra =
        e.whatToDo.empty() ? QString()
                           : QStringLiteral("<p style=\"margin:4px 0\"><i>What to do:</i> %1</p>").arg(esc(e.whatToDo));
    return page(QStringLiteral("%1%2 &nbsp;%3").arg(codePrefix.toHtmlEscaped(), esc(e.codeText), esc(e.message)), esc(e.severity), {}, e.meaning,
                e.manualLines, extra);
}

} // namespace editor
