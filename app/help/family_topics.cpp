// FamilyTopics: the SC750 and PMC-960 references as help topics, from their catalogs.
#include "family_topics.h"

#include "editor/mpl_help.h"
#include "editor/servobasic_help.h"

#include "drive_core/catalog/pmc960_catalog.h"
#include "drive_core/catalog/sc750_catalog.h"

#include <QObject>

namespace app {

namespace {

QString str(std::string_view text) {
    return QString::fromUtf8(text.data(), qsizetype(text.size()));
}

ReferenceTopic topic(ReferenceTopic::Kind kind, const QString& key, const QString& title, const QString& summary,
                     const QString& html) {
    return {kind, key, title, summary, html};
}

QString sc750Intro() {
    return QObject::tr(
        "<h2>ServoDesk for the SC750 (Motion Dialogue)</h2>"
        "<p>ServoBASIC Plus programs (<code>.bas</code>) are compiled on the PC into a <code>.BIN</code> and "
        "downloaded to the controller, which runs them. ServoDesk talks to the controller on a serial port (9600 "
        "baud, axis 255 = RS-232, 0-254 multidrop) or to the built-in simulated SC750.</p>"
        "<h3>Compile menu</h3>"
        "<table cellspacing=4>"
        "<tr><td><b>Ctrl+R</b></td><td>Run: compile if needed, download, run, open the Output window</td></tr>"
        "<tr><td><b>Ctrl+C</b></td><td>Stop the program (it can be continued)</td></tr>"
        "<tr><td><b>F5</b></td><td>Continue after a stop or a breakpoint</td></tr>"
        "<tr><td><b>Alt+R</b></td><td>Reset the program to its first line</td></tr>"
        "<tr><td><b>F9</b></td><td>Set or clear a breakpoint on the cursor's line (10 at most)</td></tr>"
        "<tr><td><b>F4</b></td><td>Output window: the program's PRINT and INPUT</td></tr>"
        "</table>"
        "<p>A program starts with its PARAMS block (File &gt; Create Program writes one; Options &gt; Controller "
        "Set Up computes it for a motor), then its DIMs, the main body ending in END, SUBs and INTERRUPT "
        "routines. The compiler stops at the first error and shows its line.</p>"
        "<p>F1 on a word in the editor explains it; this reference lists every statement, function, "
        "predefined variable, parameter and fault code.</p>");
}

QString pmc960Intro() {
    return QObject::tr(
        "<h2>ServoDesk for the ORMEC PMC-960 (MPL)</h2>"
        "<p>MPL is typed at the controller's prompt <code>}</code> (after the axis ID, e.g. <code>= }</code>) "
        "one character at a time: a command runs as soon as its last character arrives, so "
        "<code>A?</code> answers at once and <code>A3500</code> waits for a terminator (CR, a space, "
        "<code>+ - * , ;</code>). The Terminal talks to the controller; Esc (MPL &gt; Stop) aborts a running "
        "program, a wait or a half-typed command.</p>"
        "<h3>Programs</h3>"
        "<p>The program buffer (about 1,940 bytes) holds labelled sequences, <code>@A</code> to <code>@Z</code> "
        "and more; <code>E@A</code> executes one. MPL &gt; Download Program writes the editor's program into the "
        "buffer and compares the controller's communications checksum with ours; Upload reads it back.</p>"
        "<h3>Status and errors</h3>"
        "<p>The status panel polls the controller with the attention byte (1DH) and a letter, answered at "
        "any time without disturbing the program. Errors arrive as <code>#xx</code> codes (the Error codes "
        "group below), E-codes asynchronously.</p>");
}

} // namespace

const QList<ReferenceTopic>& FamilyTopics::sc750() {
    namespace cat = drive_core::catalog::sc750;
    static const QList<ReferenceTopic> topics = [] {
        QList<ReferenceTopic> out;
        out << topic(ReferenceTopic::Kind::Page, QStringLiteral("intro"), QObject::tr("General"), {}, sc750Intro());
        for (const cat::StatementInfo& s : cat::statements())
            out << topic(ReferenceTopic::Kind::Command, str(s.name), str(s.name), str(s.description),
                         editor::servoBasicHelpHtml(str(s.name)));
        for (const cat::FunctionInfo& f : cat::functions())
            out << topic(ReferenceTopic::Kind::Command, str(f.name), QObject::tr("%1 (function)").arg(str(f.name)),
                         str(f.description), editor::servoBasicHelpHtml(str(f.name)));
        for (const cat::VariableInfo& v : cat::variables())
            out << topic(ReferenceTopic::Kind::Variable, str(v.name), str(v.name), str(v.description),
                         editor::servoBasicHelpHtml(str(v.name)));
        for (const cat::FaultInfo& f : cat::faults()) {
            const QString key = QStringLiteral("FAULT %1").arg(f.code);
            const QString html = QObject::tr("<b>FAULTCODE %1</b> — front panel <b>%2</b><p><b>SC752/SC753:</b> "
                                             "%3</p><p><b>SC754/SC755/SC756:</b> %4</p><p><i>Manual %5</i></p>")
                                     .arg(f.code)
                                     .arg(str(f.display).toHtmlEscaped(), str(f.sc752).toHtmlEscaped(),
                                          str(f.sc754).toHtmlEscaped(), str(f.manualLines));
            out << topic(ReferenceTopic::Kind::Error, key,
                         QObject::tr("%1 (display %2) %3").arg(key, str(f.display), str(f.sc752)),
                         str(f.sc752) + QLatin1Char(' ') + str(f.sc754), html);
        }
        return out;
    }();
    return topics;
}

const QList<ReferenceTopic>& FamilyTopics::pmc960() {
    namespace cat = drive_core::catalog::pmc960;
    static const QList<ReferenceTopic> topics = [] {
        QList<ReferenceTopic> out;
        out << topic(ReferenceTopic::Kind::Page, QStringLiteral("intro"), QObject::tr("Introduction"), {},
                     pmc960Intro());
        for (const cat::CommandInfo& c : cat::commands()) {
            const bool parameter = cat::findParameter(c.name) != nullptr;
            out << topic(parameter ? ReferenceTopic::Kind::Variable : ReferenceTopic::Kind::Command, str(c.name),
                         QStringLiteral("%1 — %2").arg(str(c.name), str(c.longName)), str(c.description),
                         editor::mplHelpHtml(str(c.name)));
        }
        for (const cat::ErrorInfo& e : cat::errors()) {
            if (e.reserved) continue;
            const QString key = QStringLiteral("#%1").arg(e.code, 2, 16, QLatin1Char('0')).toUpper();
            out << topic(ReferenceTopic::Kind::Error, key, QStringLiteral("%1 %2").arg(key, str(e.message)),
                         str(e.meaning), editor::mplHelpHtml(key));
        }
        return out;
    }();
    return topics;
}

const QList<ReferenceTopic>& FamilyTopics::of(drive_core::DriveFamily family) {
    switch (family) {
    case drive_core::DriveFamily::Sc750: return sc750();
    case drive_core::DriveFamily::Pmc960: return pmc960();
    default: return ReferenceTopics::all();
    }
}

QStringList FamilyTopics::groupNames(drive_core::DriveFamily family) {
    switch (family) {
    case drive_core::DriveFamily::Sc750:
        return {QObject::tr("General"), QObject::tr("Statements and functions"),
                QObject::tr("Variables and parameters"), QObject::tr("Fault codes")};
    case drive_core::DriveFamily::Pmc960:
        return {QObject::tr("Introduction"), QObject::tr("Commands"), QObject::tr("Parameters"),
                QObject::tr("Error codes")};
    default:
        return {QObject::tr("Introduction"), QObject::tr("Commands"), QObject::tr("Variables"), QObject::tr("Errors")};
    }
}

std::optional<ReferenceTopic> FamilyTopics::find(drive_core::DriveFamily family, const QString& name) {
    if (family != drive_core::DriveFamily::Sc750 && family != drive_core::DriveFamily::Pmc960)
        return ReferenceTopics::find(name);
    const QString wanted = name.trimmed();
    for (const ReferenceTopic& t : of(family))
        if (t.key.compare(wanted, Qt::CaseInsensitive) == 0) return t;
    return std::nullopt;
}

QString FamilyTopics::html(const ReferenceTopic& topic) {
    return topic.html.isEmpty() ? ReferenceTopics::html(topic) : topic.html;
}

} // namespace app
