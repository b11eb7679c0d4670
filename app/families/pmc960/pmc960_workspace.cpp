// Pmc960Workspace: link and session lifetime, the MPL menu, and the docks that follow the session.
#include "pmc960_workspace.h"

#include "app/tuning/tuning_panel.h"

#include "pmc960_program_transfer.h"
#include "pmc960_routine_runner.h"
#include "pmc960_status_dock.h"

#include "families/pmc960/pmc960_error_source.h"
#include "serialport/pmc960_drive_session.h"
#include "main_window.h"
#include "resources/resources.h"
#include "scope/session_watch_source.h"
#include "scope/watch_view.h"
#include "variables/variable_browser.h"

#include <QDockWidget>
#include <QMenu>
#include <QStyle>

namespace app {

namespace {
constexpr char kEsc = '\x1b';
}

Pmc960Workspace::Pmc960Workspace(MainWindow& mainWindow)
    : SessionWorkspace(mainWindow, drive_core::DriveFamily::Pmc960), m_transfer(new Pmc960ProgramTransfer(*this)),
      m_status(new Pmc960StatusDock(&mainWindow)),
      m_parameters(new QDockWidget(tr("Variables \u2014 PMC-960 Parameter Table"), &mainWindow)),
      m_parameterBrowser(new VariableBrowser(SessionHost::of(*this), m_parameters)),
      m_menu(new QMenu(tr("&MPL"), &mainWindow)), m_errors(new Pmc960ErrorSource(*this)),
      m_runner(new Pmc960RoutineRunner(*this)) {
    // The PMC-960's variable browser is its parameter table: the dock carries the family's "Variables" title.
    m_parameters->setObjectName(QStringLiteral("pmc960ParameterDock"));
    m_parameters->setWidget(m_parameterBrowser);
    m_menu->setObjectName(QStringLiteral("mplMenu"));
    QAction* download = m_menu->addAction(tr("&Download Program"), QKeySequence(Qt::SHIFT | Qt::Key_F5), this,
                                          [this] { m_transfer->download(window().editor()); });
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
    runRoutine->setIcon(mainWindow.style()->standardIcon(QStyle::SP_MediaPlay));
    stopAction->setIcon(mainWindow.style()->standardIcon(QStyle::SP_MediaStop));
    m_menu->addSeparator();
    m_menu->addAction(m_status->toggleViewAction());
    m_menu->addAction(m_parameters->toggleViewAction());
    m_menu->addAction(tr("&Watch Variables..."), this, &Pmc960Workspace::watchVariables)
        ->setStatusTip(tr("A rolling chart of position, following error, velocity and distance to go"));
    m_menu->addAction(tuning().action); // §4.8's procedure: gains, a test index, the tach on the bench's scope

    connect(m_runner, &Pmc960RoutineRunner::programFailed, m_errors, &Pmc960ErrorSource::addProgramError);
    connect(m_transfer, &Pmc960ProgramTransfer::busyChanged, this, [this](bool busy) {
        m_status->setPaused(busy);
        updateActions();
        emit busyChanged(busy);
    });
    updateActions();
}

Pmc960Workspace::~Pmc960Workspace() {
    // The docks belong to the window and may outlive the session: let go of it first.
    blockSignals(true); // the window is going: no status updates from the link closing
    if (m_session) {
        m_session->disconnect(this);
        m_session->disconnect(m_runner);
    }
    m_status->setSession(nullptr);
    releaseLink();
}

Pmc960RunDialog* Pmc960Workspace::runRoutine() {
    return m_runner->ask();
}

QString Pmc960Workspace::busyReason() const {
    return m_transfer->isBusy() ? tr("the program buffer is being transferred") : QString();
}

QList<QMenu*> Pmc960Workspace::menus() const {
    return {m_menu};
}

QList<QAction*> Pmc960Workspace::toolBarActions() const {
    return {action(QStringLiteral("Download Program")), nullptr, action(QStringLiteral("Run Routine")),
            action(QStringLiteral("Stop"))};
}

QList<QDockWidget*> Pmc960Workspace::docks() const {
    return {m_status, m_parameters, tuning().dock};
}

QAction* Pmc960Workspace::action(const QString& text) const {
    for (QAction* a : m_menu->actions()) {
        QString plain = a->text();
        plain.remove(QLatin1Char('&')).remove(QStringLiteral("..."));
        if (plain == text) return a;
    }
    return nullptr;
}

void Pmc960Workspace::sessionCreated(serialport::DriveSession& session) {
    m_session = &static_cast<serialport::Pmc960DriveSession&>(session).pmc960();
    connect(m_session, &serialport::Pmc960Session::stateChanged, this, &Pmc960Workspace::statusChanged);
    connect(m_session, &serialport::Pmc960Session::shownReceived, this, &Pmc960Workspace::terminalReceived);
    connect(m_session, &serialport::Pmc960Session::shownReceived, m_runner, &Pmc960RoutineRunner::onShown);
    connect(m_session, &serialport::Pmc960Session::asyncError, this, [this](int code, const QString&) {
        if (m_runner->explainRefusal(code)) return; // said with what to do about the routine
        emit message(tr("PMC-960: %1").arg(Pmc960ProgramTransfer::describeError(code)));
    });
}

bool Pmc960Workspace::typeIntoTerminal(const QByteArray& bytes, bool urgent) {
    if (!isConnected()) {
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

void Pmc960Workspace::sessionOpened() {
    // (After a lost connection too: the session asks for the prompt again, the docks poll again.)
    m_status->setSession(m_session);
    m_parameterBrowser->readAll(); // every parameter's stored and in-use value, once
    // The first connection shows the status panel, so the user sees the controller at once.
    if (!m_status->isVisible()) m_status->show();
}

void Pmc960Workspace::sessionClosed() {
    m_status->setSession(nullptr);
    m_runner->reset();
}

void Pmc960Workspace::sessionEnding() {
    sessionClosed();
    m_transfer->forgetProgram(); // another connection may reach another controller
    m_session->disconnect(this);
    m_session->disconnect(m_runner);
    m_session = nullptr;
}

ErrorSource* Pmc960Workspace::errorSource() const {
    return m_errors;
}

QString Pmc960Workspace::sampleProgram() const {
    return resources::kPmc960SampleProgram;
}

QString Pmc960Workspace::statusText() const {
    if (!hasLink()) return tr("PMC-960: not connected");
    if (isReconnecting()) return tr("PMC-960 on %1: connection lost, reconnecting\u2026").arg(linkText());
    if (!isConnected()) return tr("PMC-960 on %1: connecting\u2026").arg(linkText());
    using State = serialport::Pmc960Session::State;
    QString state;
    switch (m_session->state()) {
    case State::Closed: state = tr("closed"); break;
    case State::WaitingForPrompt: state = tr("waiting for the prompt"); break;
    case State::Ready: state = tr("Ready"); break;
    case State::Busy: state = tr("Busy"); break;
    }
    return tr("PMC-960 axis %1 on %2, %3").arg(QChar(m_session->axisId())).arg(linkText(), state);
}

void Pmc960Workspace::stop() {
    if (!isConnected()) return;
    if (m_transfer->isBusy() && m_transfer->progressDialog()) {
        // ESC goes out now; the download leaves the editor and protects the buffer.
        m_transfer->cancelDownload();
        emit message(tr("Stop: ESC sent to the PMC-960; the download is cancelled"));
        return;
    }
    m_session->cancelPending();
    m_runner->reset(); // the prompt after ESC ends no routine of ours
    link()->write(QByteArray(1, kEsc));
    emit message(tr("Stop: ESC sent to the PMC-960"));
}

void Pmc960Workspace::updateActions() {
    const bool ready = isConnected() && !m_transfer->isBusy();
    for (const QString& text :
         {QStringLiteral("Download Program"), QStringLiteral("Upload Program"), QStringLiteral("Run Routine")})
        if (QAction* a = action(text)) a->setEnabled(ready);
    if (QAction* a = action(QStringLiteral("Stop"))) a->setEnabled(isConnected());
}

} // namespace app
