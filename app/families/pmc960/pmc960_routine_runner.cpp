// Pmc960RoutineRunner: the Run Routine dialog, the typed SM2 and B<label>, what their refusals mean, and where
// in its program a routine stopped.
#include "pmc960_routine_runner.h"

#include "pmc960_program_transfer.h"
#include "pmc960_run_dialog.h"
#include "pmc960_status_dock.h"
#include "pmc960_workspace.h"

#include "main_window.h"
#include "terminal_widget.h"
#include "transfer_reporter.h"

#include "drive_core/pmc960/pmc960_error_place.h"
#include "drive_core/pmc960/pmc960_program.h"
#include "editor/program_editor.h"
#include "serialport/pmc960_download.h"
#include "serialport/pmc960_session.h"

#include <QAction>
#include <QStatusBar>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace app {

namespace {
constexpr int kServoNotEnabled = 0xB6;
constexpr int kLabelUndefined = 0xC2;
constexpr int kInvalidLabel = 0xC5;
constexpr int kMaxShown = 256; // a prompt is 4 bytes: the tail is all that is looked at
const QString kEnableServo = QStringLiteral("SM2");

// "CR LF <id> }": the controller is back at its prompt.
bool endsInPrompt(const QByteArray& bytes) {
    return bytes.size() >= 4 && bytes.endsWith('}') && bytes.at(bytes.size() - 4) == '\r' &&
           bytes.at(bytes.size() - 3) == '\n';
}

// The program as the controller stores it: no spaces, no empty lines (what the download sends).
std::vector<std::string> storedLines(const QString& text) {
    std::vector<std::string> lines;
    for (const QString& line : serialport::Pmc960Download::programLines(text)) lines.push_back(line.toStdString());
    return lines;
}

bool defines(const QString& program, QChar label) {
    for (const QString& line : serialport::Pmc960Download::programLines(program))
        if (line.size() >= 2 && line.at(0) == QLatin1Char('@') && line.at(1) == label) return true;
    return false;
}

Pmc960RunDialog::Servo servoFrom(const QString& mode) {
    if (mode.startsWith(QStringLiteral("SM0"))) return Pmc960RunDialog::Servo::Disabled;
    if (mode.startsWith(QStringLiteral("SM"))) return Pmc960RunDialog::Servo::Enabled;
    return Pmc960RunDialog::Servo::Unknown; // not read yet (a dash)
}
} // namespace

Pmc960RoutineRunner::Pmc960RoutineRunner(Pmc960Workspace& workspace) : QObject(&workspace), m_workspace(workspace) {}

Pmc960RunDialog* Pmc960RoutineRunner::ask() {
    QString why;
    if (!m_workspace.session())
        why = tr("Not connected to a PMC-960: Drive > Connect first.");
    else if (isRunning())
        why = tr("Routine %1 is still running: MPL > Stop ends it.").arg(m_label);
    if (!why.isEmpty()) {
        m_workspace.window().statusBar()->showMessage(why, TransferReporter::kStatusMs);
        return nullptr;
    }
    if (m_dialog) {
        m_dialog->raise();
        return m_dialog;
    }
    const editor::ProgramEditor* editor = m_workspace.window().editor();
    const auto routines = Pmc960RunDialog::routinesIn(editor ? editor->text() : QString());
    const auto servo = servoFrom(m_workspace.statusDock()->value(QStringLiteral("mode")));
    m_dialog = new Pmc960RunDialog(routines, servo, &m_workspace.window());
    m_dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(m_dialog, &Pmc960RunDialog::runRequested, this, &Pmc960RoutineRunner::run);
    m_dialog->open();
    return m_dialog;
}

void Pmc960RoutineRunner::run(QChar label, bool enableServoFirst) {
    if (!m_workspace.session()) return;
    reset();
    m_label = label;
    if (enableServoFirst) m_steps << kEnableServo;
    m_steps << QStringLiteral("B") + label;
    say(tr("Routine %1: %2 typed at the PMC-960's prompt; its output is in the Terminal, MPL > Stop ends it.")
            .arg(label)
            .arg(m_steps.join(tr(", then "))));
    // A half-typed Terminal line would run into ours: erased as the Terminal erases it (backspaces).
    m_workspace.window().terminal()->discardTypedLine();
    sendNext();
}

void Pmc960RoutineRunner::sendNext() {
    serialport::Pmc960Session* session = m_workspace.session();
    if (!session || m_steps.isEmpty()) return;
    m_onLine = m_steps.takeFirst().toLatin1();
    m_shown.clear();
    m_promptSeen = false;
    m_refused = 0;
    // Typed, not queued: a routine gives its prompt only when it ends, and its output belongs in the Terminal.
    session->sendTyped(m_onLine + '\r');
}

void Pmc960RoutineRunner::onShown(const QByteArray& bytes) {
    if (m_onLine.isEmpty() || m_promptSeen) return;
    m_shown.append(bytes);
    if (m_shown.size() > kMaxShown) m_shown.remove(0, m_shown.size() - kMaxShown);
    if (!endsInPrompt(m_shown)) return;
    m_promptSeen = true;
    // The session reports the prompt's #xx (asyncError) right after showing it: the step is judged once it has,
    // and the next one is typed once the session has taken the prompt as the end of ours.
    QMetaObject::invokeMethod(this, &Pmc960RoutineRunner::stepDone, Qt::QueuedConnection);
}

void Pmc960RoutineRunner::noteTyped(const QByteArray& bytes) {
    for (const char c : bytes) {
        if (c == '\b' || c == '\x7f') {
            m_typedLine.chop(1);
        } else if (c == '\x1b' || c == '\x18') { // ESC, and the Terminal's Ctrl+X: the line is dropped
            m_typedLine.clear();
        } else if (c == '\r') {
            const QByteArray line = std::exchange(m_typedLine, {}).replace(' ', QByteArray());
            const bool branch = line.size() == 2 && (line.at(0) == 'B' || line.at(0) == 'b') &&
                                drive_core::pmc960::Pmc960Program::validLabel(line.at(1));
            if (!branch || isRunning() || m_placeRead != 0) continue;
            reset();
            m_label = QChar::fromLatin1(line.at(1));
            m_onLine = line;
            m_typed = true;
        } else if (c >= 0x20 && c < 0x7f) {
            m_typedLine += c;
        }
    }
}

bool Pmc960RoutineRunner::explainRefusal(int code) {
    if (m_onLine.isEmpty()) return false;
    const QString line = QString::fromLatin1(m_onLine);
    const QString error = Pmc960ProgramTransfer::describeError(code);
    if (line == kEnableServo) {
        if (serialport::Pmc960Session::isAsynchronous(code)) return false;
        m_refused = code;
        say(tr("Error: the PMC-960 refused SM2: %1 Routine %2 was not run.").arg(error).arg(m_label));
        return true;
    }
    if (isProgramError(code)) {
        if (m_stopped == 0) m_stopped = code; // said once SB& has told where (stepDone)
        return true;
    }
    m_refused = code;
    QString text = tr("Error: the PMC-960 refused routine %1 (%2): %3").arg(m_label).arg(line, error);
    const QAction* download = m_workspace.action(QStringLiteral("Download Program"));
    const QString keys = download ? download->shortcut().toString(QKeySequence::NativeText) : QString();
    text += tr(" The program in the drive may differ from the editor's: download it (MPL > Download Program%1) and "
               "run the routine again.")
                .arg(keys.isEmpty() ? QString() : QStringLiteral(", ") + keys);
    say(text);
    return true;
}

// B<label><cr> itself is refused only over its label (L1075-1091): #C5 a character no label can be, #C2 a label
// no line of the buffer starts with. The buffer's program is known from the last download verified in this
// connection; without one a #C2 is taken as B's (its hint says to download). Any other code at the prompt came
// from inside the routine B started: B moves nothing and checks nothing else.
bool Pmc960RoutineRunner::refusedByB(int code) const {
    if (code == kInvalidLabel) return true;
    if (code != kLabelUndefined) return false;
    const QString program = m_workspace.transfer().downloadedProgram();
    return program.isNull() || !defines(program, m_label);
}

bool Pmc960RoutineRunner::isProgramError(int code) const {
    return !m_onLine.isEmpty() && m_onLine != kEnableServo.toLatin1() && m_promptSeen && !refusedByB(code);
}

void Pmc960RoutineRunner::stepDone() {
    if (m_onLine.isEmpty() || !m_promptSeen) return;
    const int refused = m_refused;
    m_onLine.clear();
    if (m_stopped != 0) return readPlace();
    if (refused != 0) {
        m_steps.clear();
        emit finished(m_label, refused);
        return;
    }
    if (!m_steps.isEmpty()) return sendNext();
    if (!m_typed) say(tr("Routine %1 ended at the prompt; its output is in the Terminal.").arg(m_label));
    emit finished(m_label, 0);
}

// The controller prints only the code; its error-status buffer keeps the last label passed and the commands
// executed since, at the time of the error (SB&, 5.3.4, 7.17.1, L1466-1474).
void Pmc960RoutineRunner::readPlace() {
    m_steps.clear();
    serialport::Pmc960Session* session = m_workspace.session();
    if (!session) return reportStop({}, tr("the controller is not connected"));
    connect(session, &serialport::Pmc960Session::finished, this, &Pmc960RoutineRunner::onPlaceRead,
            Qt::UniqueConnection);
    connect(session, &serialport::Pmc960Session::failed, this, &Pmc960RoutineRunner::onPlaceFailed,
            Qt::UniqueConnection);
    m_placeRead = session->send("SB&");
}

void Pmc960RoutineRunner::onPlaceRead(quint64 id, const serialport::Pmc960Response& response) {
    if (id != m_placeRead || m_placeRead == 0) return;
    m_placeRead = 0;
    if (response.error != 0)
        return reportStop({}, tr("SB& was refused: %1").arg(Pmc960ProgramTransfer::describeError(response.error)));
    reportStop(response.value, {});
}

void Pmc960RoutineRunner::onPlaceFailed(quint64 id, const QString& reason) {
    if (id != m_placeRead || m_placeRead == 0) return;
    m_placeRead = 0;
    reportStop({}, tr("SB& was not answered: %1").arg(reason));
}

// sb: SB&'s answer ("H 1"), empty when unread (then unread says why). The program followed is the one
// downloaded and verified in this connection, else the editor's, which the message then says.
void Pmc960RoutineRunner::reportStop(const QString& sb, const QString& unread) {
    const int code = std::exchange(m_stopped, 0);
    if (code == 0) return;
    const Pmc960ProgramTransfer& transfer = m_workspace.transfer();
    QString program = transfer.downloadedProgram();
    const bool downloaded = !program.isNull();
    if (!downloaded) {
        const editor::ProgramEditor* editor = m_workspace.window().editor();
        program = editor ? editor->text() : QString();
    }
    const QStringList parts = sb.split(QLatin1Char(' '), Qt::SkipEmptyParts);
    bool counted = false;
    const int count = parts.size() == 2 && parts[0].size() == 1 ? parts[1].toInt(&counted) : 0;
    std::optional<drive_core::pmc960::Pmc960ErrorPlace> place;
    if (counted)
        place = drive_core::pmc960::placeProgramError(storedLines(program), m_label.toLatin1(),
                                                      parts[0].at(0).toLatin1(), count, code);

    Pmc960ProgramStop stop;
    stop.code = code;
    const QString error = Pmc960ProgramTransfer::describeError(code);
    QString text;
    if (place) {
        const QChar routine = place->routine != 0 ? QChar::fromLatin1(place->routine) : m_label;
        const QString command = QString::fromStdString(place->command);
        stop.editorLine = Pmc960ProgramTransfer::editorLineOf(program, int(place->line));
        stop.detail = tr("%1 in routine %2").arg(command, QString(routine)); // one pass: G%1 is a command
        QString how = tr("SB& %1").arg(sb);
        if (place->afterReturn) how += tr(", counted on after a called routine returned");
        if (place->ambiguous) how += tr("; @%1 begins several lines, this is the likeliest").arg(parts[0]);
        text = tr("Error: routine %1 stopped at line %2, %3 (%4): %5")
                   .arg(routine)
                   .arg(stop.editorLine)
                   .arg(command, how, error);
        if (!downloaded)
            text += tr(" (The line is the editor's program's: it was not downloaded in this connection, so the drive "
                       "may hold another.)");
    } else {
        stop.detail = tr("routine %1").arg(m_label);
        const QString why = !counted ? (unread.isEmpty() ? tr("SB& answered \"%1\"").arg(sb) : unread)
                                     : tr("SB& reads %1 (the last label passed, the commands since), which the "
                                          "program text does not lead to by straight execution")
                                           .arg(sb);
        text = tr("Error: routine %1 stopped: %2 Where in the program is not known: %3.").arg(m_label).arg(error, why);
    }
    if (code == kServoNotEnabled)
        text += tr(" Enable the servo first: tick \"Enable the servo first (SM2)\" in MPL > Run Routine, or type SM2.");
    say(text);
    emit programFailed(stop);
    emit finished(m_label, code);
}

void Pmc960RoutineRunner::reset() {
    m_steps.clear();
    m_onLine.clear();
    m_typed = false;
    m_shown.clear();
    m_promptSeen = false;
    m_refused = 0;
    m_placeRead = 0;
    if (m_stopped != 0) reportStop({}, tr("the run was stopped or the link closed before SB& was read"));
}

void Pmc960RoutineRunner::say(const QString& text) {
    m_lastMessage = text;
    emit m_workspace.message(text);
}

} // namespace app
