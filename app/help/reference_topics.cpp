// ReferenceTopics: catalog entries as topics and pages.
#include "reference_topics.h"

#include "drive_core/catalog/bds5_catalog.h"

#include <QRegularExpression>
#include <algorithm>
#include <QStringList>

namespace app {

namespace cat = drive_core::catalog::bds5;

namespace {
QString str(std::string_view text) {
    return QString::fromUtf8(text.data(), qsizetype(text.size()));
}
QString esc(std::string_view text) {
    return str(text).toHtmlEscaped();
}

QString modesText(unsigned modes) {
    QStringList names;
    if (modes & cat::kInteractive) names << QObject::tr("interactive (-->)");
    if (modes & cat::kMonitor) names << QObject::tr("monitor and single-step (==>, s-->)");
    if (modes & cat::kProgram) names << QObject::tr("user program");
    if (modes & cat::kEditor) names << QObject::tr("resident editor (e->)");
    return names.isEmpty() ? QObject::tr("none") : names.join(QStringLiteral(", "));
}

QString severityText(cat::Severity s) {
    switch (s) {
    case cat::Severity::HistoryOnly: return QObject::tr("0 \u2014 logged to ERR HIST only");
    case cat::Severity::Warning: return QObject::tr("1 \u2014 warning: message only");
    case cat::Severity::Break: return QObject::tr("2 \u2014 breaks the program, stops motion at AMAX");
    case cat::Severity::Disable: return QObject::tr("3 \u2014 breaks the program and disables the drive");
    case cat::Severity::Firmware: return QObject::tr("4 \u2014 firmware: CPU LED blinks, communications stop");
    }
    return {};
}

QString writeText(cat::WriteCondition w) {
    switch (w) {
    case cat::WriteCondition::Always: return QObject::tr("any time");
    case cat::WriteCondition::Disabled: return QObject::tr("only while the drive is disabled (ERR 51)");
    case cat::WriteCondition::NoMotion: return QObject::tr("only with no commanded motion");
    case cat::WriteCondition::Never: return QObject::tr("never: a monitor variable (ERR 81)");
    case cat::WriteCondition::Factory: return QObject::tr("factory only (ERR 111)");
    }
    return {};
}

QString limitsText(const cat::VariableInfo& v) {
    if (v.isSwitch || v.limits == cat::LimitClass::Switch) return QObject::tr("switch: 0 (OFF) or 1 (ON)");
    if (v.limits == cat::LimitClass::None) return QObject::tr("not checked");
    return QStringLiteral("%1 \u2026 %2").arg(cat::minimumOf(v)).arg(cat::maximumOf(v));
}

QString row(const QString& name, const QString& value) {
    return QStringLiteral("<tr><th align=left valign=top style='padding-right:12px'>%1</th><td>%2</td></tr>")
        .arg(name, value);
}

QString page(const QString& heading, const QString& subtitle, const QString& rows, const QString& body) {
    return QStringLiteral("<h2 style='margin-bottom:2px'>%1</h2><p style='margin-top:0'><i>%2</i></p>"
                          "<table cellspacing=2>%3</table><p>%4</p>")
        .arg(heading, subtitle, rows, body);
}

QList<ReferenceTopic> build() {
    QList<ReferenceTopic> topics;
    topics.append({ReferenceTopic::Kind::Page, QStringLiteral("intro"), QObject::tr("Introduction"),
                   QObject::tr("Getting started with ServoDesk and the BDS5")});
    for (const cat::CommandInfo& c : cat::commands())
        topics.append({ReferenceTopic::Kind::Command, str(c.name),
                       QStringLiteral("%1 \u2014 %2").arg(str(c.name), str(c.longName)), str(c.description)});
    for (const cat::VariableInfo& v : cat::variables()) {
        const QString range =
            v.lastIndex > 0 ? QStringLiteral("%1%2\u2013%1%3").arg(str(v.name)).arg(v.firstIndex).arg(v.lastIndex)
                            : str(v.name);
        topics.append({ReferenceTopic::Kind::Variable, str(v.name), range, str(v.description)});
    }
    for (const cat::ErrorInfo& e : cat::errors())
        topics.append({ReferenceTopic::Kind::Error, QStringLiteral("ERR %1").arg(e.code),
                       QStringLiteral("ERR %1 %2").arg(e.code).arg(str(e.message)), str(e.meaning)});
    return topics;
}
} // namespace

const QList<ReferenceTopic>& ReferenceTopics::all() {
    static const QList<ReferenceTopic> topics = build();
    return topics;
}

std::optional<ReferenceTopic> ReferenceTopics::find(const QString& name) {
    const QString key = name.trimmed().toUpper();
    static const QRegularExpression kError(QStringLiteral("^(?:ERR\\s*)?(\\d+)$"));
    const auto error = kError.match(key);
    const QString wanted = error.hasMatch() ? QStringLiteral("ERR %1").arg(error.captured(1).toInt()) : key;
    if (key == QLatin1String("INTRO")) return all().first();
    for (const auto kind : {ReferenceTopic::Kind::Error, ReferenceTopic::Kind::Command, ReferenceTopic::Kind::Variable})
        for (const ReferenceTopic& t : all())
            if (t.kind == kind && t.key == wanted) return t;
    if (const auto ref = cat::findVariable(key.toStdString())) { // X12 -> X
        const QString family = str(ref->info->name);
        for (const ReferenceTopic& t : all())
            if (t.kind == ReferenceTopic::Kind::Variable && t.key == family) return t;
    }
    return std::nullopt;
}

bool ReferenceTopics::matches(const ReferenceTopic& topic, const QString& search) {
    const QString s = search.trimmed();
    if (s.isEmpty()) return true;
    return topic.key.startsWith(s, Qt::CaseInsensitive) || topic.title.contains(s, Qt::CaseInsensitive) ||
           topic.summary.contains(s, Qt::CaseInsensitive);
}

QString ReferenceTopics::html(const ReferenceTopic& topic) {
    const std::string key = topic.key.toStdString();
    switch (topic.kind) {
    case ReferenceTopic::Kind::Page:
        return introHtml();
    case ReferenceTopic::Kind::Command: {
        const cat::CommandInfo* c = cat::findCommand(key);
        if (!c) return {};
        QString rows = row(QObject::tr("Syntax"), QStringLiteral("<code>%1</code>").arg(esc(c->syntax)));
        rows += row(QObject::tr("Modes"), modesText(c->modes));
        rows += row(QObject::tr("Entries"), QObject::tr("%1 to %2 after the command").arg(c->minEntries).arg(c->maxEntries));
        if (c->idling) rows += row(QObject::tr("Idling"), QObject::tr("yes: lower-priority tasks run while it waits"));
        if (c->version3) rows += row(QObject::tr("Firmware"), QObject::tr("added in v3.0.0"));
        rows += row(QObject::tr("Manual"), esc(c->manualLines));
        return page(esc(c->name), esc(c->longName), rows, esc(c->description));
    }
    case ReferenceTopic::Kind::Variable: {
        const auto found = std::find_if(cat::variables().begin(), cat::variables().end(),
                                        [&key](const cat::VariableInfo& v) { return v.name == key; });
        if (found == cat::variables().end()) return {};
        const cat::VariableInfo& v = *found;
        QString rows;
        if (v.lastIndex > 0) rows += row(QObject::tr("Indexed"), QStringLiteral("%1%2 \u2026 %1%3").arg(esc(v.name)).arg(v.firstIndex).arg(v.lastIndex));
        rows += row(QObject::tr("Units"), v.units.empty() ? QObject::tr("none") : esc(v.units));
        rows += row(QObject::tr("Limits"), limitsText(v));
        rows += row(QObject::tr("Written"), writeText(v.write));
        rows += row(QObject::tr("At power-up"),
                    v.persistence == cat::Persistence::Remembered
                        ? QObject::tr("remembered (factory value %1, basic units)").arg(v.powerUpValue)
                        : QObject::tr("%1 in basic units (not remembered)").arg(v.powerUpValue));
        if (v.version3) rows += row(QObject::tr("Firmware"), QObject::tr("added in v3.0.0"));
        rows += row(QObject::tr("Manual"), esc(v.manualLines));
        return page(esc(v.name), v.isSwitch ? QObject::tr("switch") : QObject::tr("variable"), rows, esc(v.description));
    }
    case ReferenceTopic::Kind::Error: {
        const cat::ErrorInfo* e = cat::findError(topic.key.mid(4).toInt());
        if (!e) return {};
        QString rows = row(QObject::tr("Message"), QStringLiteral("<code>ERR %1 %2</code>").arg(e->code).arg(esc(e->message)));
        rows += row(QObject::tr("Severity"), severityText(e->severity));
        rows += row(QObject::tr("Manual"), esc(e->manualLines));
        QString body = esc(e->meaning);
        if (!e->remedy.empty()) body += QStringLiteral("</p><p><b>%1</b> %2").arg(QObject::tr("Remedy:"), esc(e->remedy));
        return page(QStringLiteral("ERR %1").arg(e->code), esc(e->message), rows, body);
    }
    }
    return {};
}

} // namespace app
