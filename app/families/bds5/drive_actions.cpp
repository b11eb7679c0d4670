// DriveActions: what each drive action sends, and when it may be used.
#include "drive_actions.h"

#include "drive_connection.h"
#include "main_window.h"
#include "run_label_dialog.h"
#include "drive/terminal_widget.h"

#include "editor/program_editor.h"

#include <QAction>
#include <QMenu>
#include <QStyle>
#include <QToolBar>

namespace app {

namespace {
using serialport::Bds5Mode;
constexpr char kCtrlX = '\x18';
constexpr char kCtrlV = '\x16';
constexpr char kEscape = '\x1b';
} // namespace

DriveActions::DriveActions(MainWindow& window) : QObject(&window), m_window(window) {
    QStyle* style = window.style();
    m_run = make(tr("&Run Label..."), tr("RUN a label of the program in the drive"), tr("Ctrl+Shift+R"),
                 QStringLiteral("runAction"));
    m_run->setIcon(style->standardIcon(QStyle::SP_MediaPlay));
    m_break = make(tr("&Break"), tr("Break the program (B); the drive goes back to its --> prompt"),
                   QString(), QStringLiteral("breakAction"));
    m_break->setIcon(style->standardIcon(QStyle::SP_MediaPause));
    m_stop = make(tr("&Stop Motion (^X)"),
                  tr("^X: stop motion and break, at once, in any mode, ahead of anything queued"),
                  tr("Ctrl+Shift+X"), QStringLiteral("stopAction"));
    m_stop->setIcon(style->standardIcon(QStyle::SP_MediaStop));
    m_kill = make(tr("&Kill"), tr("Kill (K): break, stop at once and disable the drive"), QString(),
                  QStringLiteral("killAction"));
    m_kill->setIcon(style->standardIcon(QStyle::SP_BrowserStop));
    m_enable = make(tr("&Enable"), tr("Enable the drive (EN)"), QString(), QStringLiteral("enableAction"));
    m_disable = make(tr("D&isable"), tr("Disable the drive (DIS)"), QString(), QStringLiteral("disableAction"));
    m_monitor = make(tr("&Monitor (Esc)"),
                     tr("Esc: from a running program to monitor mode (==>), and back to running"), QString(),
                     QStringLiteral("monitorAction"));
    m_singleStep = make(tr("Single-S&tep"), tr("Single-step the program (SS ON / SS OFF)"), QString(),
                        QStringLiteral("singleStepAction"));
    m_singleStep->setCheckable(true);
    m_trace = make(tr("Tr&ace"), tr("Trace every program line as it runs (TRC ON / TRC OFF)"), QString(),
                   QStringLiteral("traceAction"));
    m_trace->setCheckable(true);
    m_variableInput = make(tr("&Variable Input (^V)"), tr("^V: start the program's VARIABLE$ task"), QString(),
                           QStringLiteral("variableInputAction"));
    m_step = make(tr("Ste&p"), tr("Run the line shown at the single-step prompt (Enter)"), tr("F8"),
                  QStringLiteral("stepAction"));
    m_step->setIcon(style->standardIcon(QStyle::SP_ArrowForward));
    m_continue = make(tr("C&ontinue"), tr("Leave single-step and let the program run on (SS OFF)"), tr("F9"),
                      QStringLiteral("continueAction"));
    m_continue->setIcon(style->standardIcon(QStyle::SP_MediaSeekForward));

    connect(m_run, &QAction::triggered, this, &DriveActions::askRunLabel);
    connect(m_break, &QAction::triggered, this, [this] { breakOrKill(QStringLiteral("B")); });
    connect(m_kill, &QAction::triggered, this, [this] { breakOrKill(QStringLiteral("K")); });
    connect(m_stop, &QAction::triggered, this,
            [this] { m_window.connection().sendUrgent(QByteArray(1, kCtrlX)); });
    connect(m_enable, &QAction::triggered, this, [this] { command(QStringLiteral("EN")); });
    connect(m_disable, &QAction::triggered, this, [this] { command(QStringLiteral("DIS")); });
    connect(m_monitor, &QAction::triggered, this,
            [this] { m_window.connection().sendUrgent(QByteArray(1, kEscape)); });
    connect(m_singleStep, &QAction::triggered, this, &DriveActions::setSingleStep);
    connect(m_trace, &QAction::triggered, this, &DriveActions::setTrace);
    connect(m_variableInput, &QAction::triggered, this,
            [this] { m_window.connection().sendRaw(QByteArray(1, kCtrlV)); });
    connect(m_step, &QAction::triggered, this, [this] { raw("\r"); });
    connect(m_continue, &QAction::triggered, this, [this] { setSingleStep(false); });

    DriveConnection& connection = m_window.connection();
    connect(&connection, &DriveConnection::modeChanged, this, &DriveActions::updateEnabled);
    connect(&connection, &DriveConnection::sessionStateChanged, this, &DriveActions::updateEnabled);
    connect(&connection, &DriveConnection::connectedChanged, this, &DriveActions::updateEnabled);
    connect(&connection, &DriveConnection::linkChanged, this, &DriveActions::updateEnabled);
    connect(&connection, &DriveConnection::linkChanged, this, &DriveActions::watchSession);
    watchSession();
    updateEnabled();
}

QAction* DriveActions::make(const QString& text, const QString& tip, const QString& shortcut,
                            const QString& name) {
    auto* action = new QAction(text, this);
    action->setObjectName(name);
    action->setToolTip(tip);
    action->setStatusTip(tip);
    if (!shortcut.isEmpty()) action->setShortcut(QKeySequence(shortcut));
    return action;
}

QList<QAction*> DriveActions::menuActions() const {
    return {nullptr,   m_run,        m_break, m_stop,     m_kill,  nullptr,         m_enable, m_disable,
            nullptr,   m_monitor,    m_singleStep, m_step, m_continue, m_trace, m_variableInput};
}

QToolBar* DriveActions::createDriveToolBar() {
    auto* bar = new QToolBar(tr("Drive"), &m_window);
    bar->setObjectName(QStringLiteral("driveToolBar"));
    bar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    bar->addActions({m_run, m_stop, m_kill}); // Break is on the debug toolbar, beside Step and Continue
    bar->addSeparator();
    bar->addActions({m_enable, m_disable, m_monitor, m_variableInput});
    return bar;
}

QToolBar* DriveActions::createDebugToolBar() {
    auto* bar = new QToolBar(tr("Debug"), &m_window);
    bar->setObjectName(QStringLiteral("debugToolBar"));
    bar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    bar->addActions({m_singleStep, m_trace});
    bar->addSeparator();
    bar->addActions({m_step, m_continue, m_break});
    return bar;
}

RunLabelDialog* DriveActions::askRunLabel() {
    // The labels of the program in the editor; the drive itself reports a label it lacks (ERR 70).
    const editor::ProgramEditor* program = m_window.editor();
    auto* dialog = new RunLabelDialog(RunLabelDialog::labelsIn(program ? program->text() : QString()), &m_window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &RunLabelDialog::runRequested, this, &DriveActions::run);
    dialog->open();
    return dialog;
}

void DriveActions::run(int label) {
    // RUN gives no prompt while the program runs: typed like the terminal, not queued for an answer.
    raw(label < 0 ? QByteArray("RUN\r") : "RUN " + QByteArray::number(label) + '\r');
}

void DriveActions::command(const QString& line) {
    m_window.terminal()->discardTypedLine(); // a half-typed line would hold the queue
    if (const quint64 id = m_window.connection().sendCommand(line)) m_outstanding.insert(id);
}

void DriveActions::raw(const QByteArray& bytes) {
    if (!m_outstanding.isEmpty()) {
        m_deferred += bytes;
        return;
    }
    m_window.terminal()->discardTypedLine();
    m_window.connection().sendRaw(bytes);
}

void DriveActions::watchSession() {
    m_outstanding.clear();
    m_deferred.clear();
    serialport::Bds5Session* session = m_window.connection().session();
    if (!session) return;
    connect(session, &serialport::Bds5Session::finished, this, [this](quint64 id) { commandDone(id); });
    connect(session, &serialport::Bds5Session::failed, this, [this](quint64 id) { commandDone(id); });
}

void DriveActions::commandDone(quint64 id) {
    if (!m_outstanding.remove(id) || !m_outstanding.isEmpty() || m_deferred.isEmpty()) return;
    raw(std::exchange(m_deferred, {}));
}

void DriveActions::breakOrKill(const QString& letter) {
    // A running program takes no input: Esc first for the monitor prompt, where B and K are allowed.
    if (mode() == Bds5Mode::Running) m_window.connection().sendUrgent(QByteArray(1, kEscape));
    command(letter);
}

void DriveActions::setSingleStep(bool on) {
    m_singleStep->setChecked(on);
    if (on) command(QStringLiteral("SS ON"));
    else if (mode() == Bds5Mode::SingleStep) raw("SS OFF\r"); // at the step prompt: the program runs on
    else command(QStringLiteral("SS OFF"));
}

void DriveActions::setTrace(bool on) {
    m_trace->setChecked(on);
    command(on ? QStringLiteral("TRC ON") : QStringLiteral("TRC OFF"));
}

Bds5Mode DriveActions::mode() const {
    const auto* session = m_window.connection().session();
    return m_window.connection().isConnected() && session ? session->mode() : Bds5Mode::Unknown;
}

void DriveActions::updateEnabled() {
    const bool connected = m_window.connection().isConnected();
    const Bds5Mode m = mode();
    const bool interactive = m == Bds5Mode::Interactive;
    const bool monitor = m == Bds5Mode::Monitor;
    const bool stepping = m == Bds5Mode::SingleStep;
    const bool running = m == Bds5Mode::Running;
    const bool atPrompt = interactive || monitor || stepping; // the monitor command subset works
    m_run->setEnabled(interactive);
    m_break->setEnabled(atPrompt || running);
    m_kill->setEnabled(atPrompt || running);
    m_stop->setEnabled(connected);
    m_enable->setEnabled(atPrompt);
    m_disable->setEnabled(atPrompt);
    m_monitor->setEnabled(running || monitor || stepping);
    m_monitor->setText(monitor ? tr("Leave &Monitor (Esc)") : tr("&Monitor (Esc)"));
    m_singleStep->setEnabled(atPrompt);
    if (stepping && m_lastMode != m) m_singleStep->setChecked(true); // SS ON typed in the terminal
    m_lastMode = m;
    m_trace->setEnabled(interactive || monitor);
    m_variableInput->setEnabled(connected);
    m_step->setEnabled(stepping);
    m_continue->setEnabled(stepping);
}

} // namespace app
