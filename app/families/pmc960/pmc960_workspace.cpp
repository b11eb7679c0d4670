// Pmc960Workspace: link and session lifetime, the MPL menu, and the docks that follow the session.
#include "pmc960_workspace.h"

#include "tuning/family_tuning_panel.h"

#include "pmc960_parameter_dock.h"
#include "pmc960_program_transfer.h"
#include "pmc960_routine_runner.h"
#include "pmc960_status_dock.h"

#include "families/pmc960/pmc960_error_source.h"
#include "main_window.h"
#include "resources/resources.h"
#include "scope/session_watch_source.h"
#include "scope/watch_view.h"

#include <QMenu>
#include <QProgressDialog>

namespace app {

namespace {
constexpr char kEsc = '\x1b';
}

Pmc960Workspace::Pmc960Workspace(MainWindow& window)
    : FamilyWorkspace(&window), m_window(window), m_transfer(new Pmc960ProgramTransfer(*this)),
      m_status(new Pmc960StatusDock(&window)), m_parameters(new Pmc960ParameterDock(&window)),
      m_menu(new QMenu(tr("&MPL"), &window)), m_errors(new Pmc960ErrorSource(*this)),
      m_runner(new Pmc960RoutineRunner(*this)), m_tuning(makeFamilyTuningDock(window, family())) {
    connect(&m_reconnector, &LinkReconnector::lost, this, [this](const QString& description) {
        emit message(tr("The connection to the PMC-960 was lost (%1). Reconnecting every second; nothing in the "
                        "editors is affected. Drive > Disconnect stops trying.")
                         .arg(description));
        emit statusChanged();
    });
    m_menu->setObjectName(QStringLiteral("mplMenu"));
    QAction* download = m_menu->addAction(tr("&Download Program"), QKeySequence(Qt::SHIFT | Qt::Key_F5), this,
                                          [this] { m_transfer->download(m_window.editor()); });
    download->setStatusTip(tr("Write the current editor's program to the PMC-960's program buffer, verified by "
                              "the communications checksum"));
    QAction* upload = m_menu->addAction(tr("&Upload Program"), QKeySequence(Qt::SHIFT | Qt::Key_F6), m_transfer,
                                        &Pmc960ProgramTransfer::upload);
    upload->setStatusTip(tr("Read the PMC-960's program buffer into a new tab"));
    // Ctrl+F5 beside Shift+F5/F6 (download, upload): free in every family (tests/app/shortcuts_test.cpp).
    QAction* runRoutine = m_menu->addAction(tr("&Run Routine..."), QKeySequence(Qt::CTRL | Qt::Key_F5), this,
                                            &Pmc960Workspace::runRoutine);
    runRoutine->setStatusTip(tr("Run a labelled routine of the editor's program (B<label>), enabling the servo "
                                "first if asked"));
    m_menu->addSeparator();
    QAction* stopAction = m_menu->addAction(tr("&Stop"), QKeySequence(tr("Ctrl+Alt+X")), this, &Pmc960Workspace::stop);
    stopAction->setStatusTip(tr("Send ESC: abort the running program, wait or half-typed command"));
    m_menu->addSeparator();
    m_menu->addAction(m_status->toggleViewAction());
    m_menu->addAction(m_parameters->toggleViewAction());
    m_menu->addAction(tr("&Watch Variables..."), this, &Pmc960Workspace::watchVariables)
        ->setStatusTip(tr("A rolling chart of position, following error, velocity and distance to go"));
    m_menu->addAction(m_tuning.action); // §4.8's procedure: gains, a test index, the tach on the bench's scope

    connect(m_runner, &Pmc960RoutineRunner::programFailed, m_errors, &Pmc960ErrorSource::addProgramError);
    connect(m_transfer, &Pmc960ProgramTransfer::busyChanged, this, [this](bool busy) {
        m_status->setPaused(busy);
        m_parameters->setPaused(busy);
        updateActions();
        emit busyChanged(busy);
    });
    updateActions();
}

Pmc960Workspace::~Pmc960Workspace() {
    // The docks belong to the window and may outlive the session: let go of it first.
    blockSignals(true); // the window is going: no status updates from the link closing
    if (m_link) m_link->disconnect(this);
    if (m_session) {
        m_session->disconnect(this);
        m_session->disconnect(m_runner);
    }
    m_status->setSession(nullptr);
    m_parameters->setSession(nullptr);
    if (m_tuning.panel) m_tuning.panel->attach(nullptr, nullptr);
}

Pmc960RunDialog* Pmc960Workspace::runRoutine() {
    return m_runner->ask();
}

QString Pmc960Workspace::busyReason() const {
    return m_transfer->isBusy() ? tr("the program buffer is being transferred") : QString();
}

WatchView* Pmc960Workspace::watchVariables() {
    if (!m_watch) m_watch = new WatchView(new SessionWatchSource(*this), &m_window);
    m_watch->show();
    m_watch->raise();
    return m_watch;
}

QList<QMenu*> Pmc960Workspace::menus() const {
    return {m_menu};
}

QList<QDockWidget*> Pmc960Workspace::docks() const {
    return {m_status, m_parameters, m_tuning.dock};
}

QAction* Pmc960Workspace::action(const QString& text) const {
    for (QAction* a : m_menu->actions()) {
        QString plain = a->text();
        plain.remove(QLatin1Char('&')).remove(QStringLiteral("..."));
        if (plain == text) return a;
    }
    return nullptr;
}

void Pmc960Workspace::activate(const ConnectionChoice& choice) {
    deactivate();
    m_link = choice.makeLink();
    m_linkText = m_link->description();
    m_drive = std::make_unique<serialport::Pmc960DriveSession>(*m_link);
    m_session = &m_drive->pmc960();
    connect(m_link.get(), &serialport::Link::opened, this, &Pmc960Workspace::onOpened);
    connect(m_link.get(), &serialport::Link::errorOccurred, this, &Pmc960Workspace::onLinkError);
    connect(m_link.get(), &serialport::Link::closed, this, [this] {
        if (!m_connected) return;
        m_connected = false;
        m_status->setSession(nullptr);
        m_parameters->setSession(nullptr);
        if (m_tuning.panel) m_tuning.panel->attach(nullptr, nullptr);
        m_runner->reset();
        updateActions();
        emit statusChanged();
    });
    m_reconnector.watch(m_link.get()); // after the handler above: lost is said once the state shows it
    connect(m_session, &serialport::Pmc960Session::stateChanged, this, &Pmc960Workspace::statusChanged);
    connect(m_session, &serialport::Pmc960Session::shownReceived, this, &Pmc960Workspace::terminalReceived);
    connect(m_session, &serialport::Pmc960Session::shownReceived, m_runner, &Pmc960RoutineRunner::onShown);
    connect(m_session, &serialport::Pmc960Session::asyncError, this, [this](int code, const QString&) {
        if (m_runner->explainRefusal(code)) return; // said with what to do about the routine
        emit message(tr("PMC-960: %1").arg(Pmc960ProgramTransfer::describeError(code)));
    });
    m_link->open();
    if (m_link->isOpen() && !m_connected) onOpened();
}

bool Pmc960Workspace::typeIntoTerminal(const QByteArray& bytes, bool urgent) {
    if (!m_connected) {
        emit message(tr("The PMC-960 is not connected (Drive > Connect): nothing was sent."));
        return true;
    }
    if (urgent && bytes == "\x1b") {
        stop();
    } else {
        m_runner->noteTyped(bytes); // a B<label> typed here is followed as MPL > Run Routine's
        m_session->sendTyped(bytes);
    }
    return true;
}

void Pmc960Workspace::onOpened() {
    if (m_connected) return;
    // (After a lost connection too: the session asks for the prompt again, the docks poll again.)
    m_connected = true;
    m_status->setSession(m_session);
    m_parameters->setSession(m_session);
    if (m_tuning.panel) m_tuning.panel->attach(m_drive.get(), m_link.get());
    updateActions();
    emit statusChanged();
    emit message(tr("Connected to %1").arg(m_linkText));
    // The first connection shows the status panel, so the user sees the controller at once.
    if (!m_status->isVisible()) m_status->show();
}

void Pmc960Workspace::onLinkError(const QString& text) {
    emit message(tr("PMC-960 link: %1").arg(text));
    if (m_link && !m_link->isOpen() && m_connected) {
        m_connected = false;
        m_status->setSession(nullptr);
        m_parameters->setSession(nullptr);
        m_runner->reset();
        updateActions();
        emit statusChanged();
    }
}

void Pmc960Workspace::deactivate() {
    m_reconnector.watch(nullptr); // closed on purpose: not lost
    const bool was = m_connected || m_link;
    m_connected = false;
    m_status->setSession(nullptr);
    m_parameters->setSession(nullptr);
    if (m_tuning.panel) m_tuning.panel->attach(nullptr, nullptr);
    m_runner->reset();
    m_transfer->forgetProgram(); // another connection may reach another controller
    if (m_session) m_session->disconnect(this);
    if (m_link) {
        m_link->disconnect(this);
        m_link->close();
    }
    m_session = nullptr;
    m_drive.reset();
    m_link.reset();
    updateActions();
    if (was) emit statusChanged();
}

ErrorSource* Pmc960Workspace::errorSource() const {
    return m_errors;
}

QString Pmc960Workspace::sampleProgram() const {
    return resources::kPmc960SampleProgram;
}

bool Pmc960Workspace::isConnected() const {
    return m_connected;
}

QString Pmc960Workspace::statusText() const {
    if (!m_link) return tr("PMC-960: not connected");
    if (isReconnecting()) return tr("PMC-960 on %1: connection lost, reconnecting\u2026").arg(m_linkText);
    if (!m_connected) return tr("PMC-960 on %1: connecting\u2026").arg(m_linkText);
    using State = serialport::Pmc960Session::State;
    QString state;
    switch (m_session->state()) {
    case State::Closed: state = tr("closed"); break;
    case State::WaitingForPrompt: state = tr("waiting for the prompt"); break;
    case State::Ready: state = tr("Ready"); break;
    case State::Busy: state = tr("Busy"); break;
    }
    return tr("PMC-960 axis %1 on %2, %3").arg(QChar(m_session->axisId())).arg(m_linkText, state);
}

void Pmc960Workspace::stop() {
    if (!m_connected) return;
    if (m_transfer->isBusy() && m_transfer->progressDialog()) {
        // ESC goes out now; the download leaves the editor and protects the buffer. (QProgressDialog::cancel()
        // would only hide the dialog: it does not emit canceled().)
        m_transfer->cancelDownload();
        emit message(tr("Stop: ESC sent to the PMC-960; the download is cancelled"));
        return;
    }
    m_session->cancelPending();
    m_runner->reset(); // the prompt after ESC ends no routine of ours
    m_link->write(QByteArray(1, kEsc));
    emit message(tr("Stop: ESC sent to the PMC-960"));
}

void Pmc960Workspace::updateActions() {
    const bool ready = m_connected && !m_transfer->isBusy();
    for (const QString& text :
         {QStringLiteral("Download Program"), QStringLiteral("Upload Program"), QStringLiteral("Run Routine")})
        if (QAction* a = action(text)) a->setEnabled(ready);
    if (QAction* a = action(QStringLiteral("Stop"))) a->setEnabled(m_connected);
}

} // namespace app
