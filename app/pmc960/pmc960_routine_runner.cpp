// Pmc960RoutineRunner: the Run Routine dialog, the typed SM2 and B<label>, and what their refusals mean.
#include "pmc960_routine_runner.h"

#include "pmc960_program_transfer.h"
#include "pmc960_run_dialog.h"
#include "pmc960_status_dock.h"
#include "pmc960_workspace.h"

#include "main_window.h"
#include "terminal_widget.h"
#include "transfer_reporter.h"

#include "editor/program_editor.h"

#include <QAction>
#include <QStatusBar>

namespace app {

namespace {
constexpr int kServoNotEnabled = 0xB6;
constexpr int kMaxShown = 256; // a prompt is 4 bytes: the tail is all that is looked at
const QString kEnableServo = QStringLiteral("SM2");

// "CR LF <id> }": the controller is back at its prompt.
bool endsInPrompt(const QByteArray& bytes) {
    return bytes.size() >= 4 && bytes.endsWith('}') && bytes.at(bytes.size() - 4) == '\r' &&
           bytes.at(bytes.size() - 3) == '\n';
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

bool Pmc960RoutineRunner::explainRefusal(int code) {
    if (m_onLine.isEmpty() || serialport::Pmc960Session::isAsynchronous(code)) return false;
    m_refused = code;
    const QString line = QString::fromLatin1(m_onLine);
    const QString error = Pmc960ProgramTransfer::describeError(code);
    if (line == kEnableServo) {
        say(tr("Error: the PMC-960 refused SM2: %1 Routine %2 was not run.").arg(error).arg(m_label));
        return true;
    }
    QString text = tr("Error: the PMC-960 refused routine %1 (%2): %3").arg(m_label).arg(line, error);
    if (code == kServoNotEnabled)
        text += tr(" Enable the servo first: tick \"Enable the servo first (SM2)\" in MPL > Run Routine, or type SM2.");
    const QAction* download = m_workspace.action(QStringLiteral("Download Program"));
    const QString keys = download ? download->shortcut().toString(QKeySequence::NativeText) : QString();
    text += tr(" The program in the drive may differ from the editor's: download it (MPL > Download Program%1) and "
               "run the routine again.")
                .arg(keys.isEmpty() ? QString() : QStringLiteral(", ") + keys);
    say(text);
    return true;
}

void Pmc960RoutineRunner::stepDone() {
    if (m_onLine.isEmpty() || !m_promptSeen) return;
    const int refused = m_refused;
    m_onLine.clear();
    if (refused != 0) {
        m_steps.clear();
        emit finished(m_label, refused);
        return;
    }
    if (!m_steps.isEmpty()) return sendNext();
    say(tr("Routine %1 ended at the prompt; its output is in the Terminal.").arg(m_label));
    emit finished(m_label, 0);
}

void Pmc960RoutineRunner::reset() {
    m_steps.clear();
    m_onLine.clear();
    m_shown.clear();
    m_promptSeen = false;
    m_refused = 0;
}

void Pmc960RoutineRunner::say(const QString& text) {
    m_lastMessage = text;
    emit m_workspace.message(text);
}

} // namespace app
