// Bds5Workspace: the BDS5's tools made once, and its connection seen through the family workspace.
#include "bds5_workspace.h"

#include "bds5_error_source.h"
#include "dep01/dep01_panel.h"
#include "wizard/setup_wizard.h"

#include "drive/capture_dock.h"
#include "drive/capture_log.h"
#include "drive_actions.h"
#include "drive_connection.h"
#include "drive/session_host.h"
#include "drive/terminal_dock.h"
#include "io_panel.h"
#include "main_window.h"
#include "resources/resources.h"
#include "scope/scope_controller.h"
#include "serialport/bds5_protocol.h"
#include "program_controller.h"
#include "variables_controller.h"
#include "variables/variables_dock.h"

#include <QMenu>
#include <QToolBar>

namespace app {

Bds5Workspace::Bds5Workspace(MainWindow& window)
    : FamilyWorkspace(&window), m_window(window), m_connection(new DriveConnection(this)),
      m_errors(new Bds5ErrorSource(*m_connection, this)) {
    DriveConnection& c = *m_connection;
    connect(&c, &DriveConnection::shownReceived, this, &FamilyWorkspace::terminalReceived);
    connect(&c, &DriveConnection::modeChanged, this, [this](serialport::Bds5Mode mode, const QString& prompt) {
        m_mode = QStringLiteral("%1 %2").arg(serialport::modeName(mode), prompt);
        emit statusChanged();
    });
    connect(&c, &DriveConnection::linkChanged, this, &FamilyWorkspace::statusChanged);
    connect(&c, &DriveConnection::sessionStateChanged, this, &FamilyWorkspace::statusChanged);
    connect(&c, &DriveConnection::connectedChanged, this, [this](bool connected) {
        if (!connected) emit message(tr("Disconnected from %1").arg(m_connection->linkDescription()));
        emit statusChanged();
    });
    connect(&c, &DriveConnection::errorOccurred, this, &FamilyWorkspace::message);
}

void Bds5Workspace::build() {
    MainWindow& w = m_window;
    m_driveActions = new DriveActions(w);
    m_toolBars = {m_driveActions->createDriveToolBar(), m_driveActions->createDebugToolBar()};

    m_programController = new ProgramController(w);
    m_variablesController = new VariablesController(w);
    m_scopeController = new ScopeController(w); // Scope menu; scope and tuning docks, hidden until used
    for (QDockWidget* dock : {m_scopeController->scopeDock(), m_scopeController->tuningDock()}) {
        w.addDockWidget(Qt::BottomDockWidgetArea, dock);
        dock->hide(); // tabbed with the terminal when first shown (ScopeController)
    }
    m_menus = {m_programController->menu(), m_variablesController->menu(), m_scopeController->menu()};

    auto* tools = new QMenu(tr("&Tools"), &w);
    tools->addAction(tr("&Setup Wizard..."), this, [this] { SetupWizard::openFor(*m_connection, &m_window); });
    m_menus << tools;

    m_captureLog = new CaptureLog(this);
    connect(m_connection, &DriveConnection::rawReceived, m_captureLog, &CaptureLog::addReceived);
    connect(m_connection, &DriveConnection::rawSent, m_captureLog, &CaptureLog::addSent);
    m_captureDock = new CaptureDock(*m_captureLog, &w);
    w.addDockWidget(Qt::BottomDockWidgetArea, m_captureDock);
    w.tabifyDockWidget(w.terminalDock(), m_captureDock);
    w.terminalDock()->raise();
    auto* capture = new QMenu(tr("Capt&ure"), &w);
    m_captureDock->addToMenu(capture);
    m_menus << capture;

    m_variablesDock = new VariablesDock(*m_connection, &w); // issue 7 docks: hidden until asked for
    m_ioPanel = new IoPanel(*m_connection, &w);
    m_dep01Panel = new Dep01Panel(*m_connection, &w);
}

QList<QDockWidget*> Bds5Workspace::docks() const {
    return {m_variablesDock, m_ioPanel,   m_dep01Panel, m_captureDock, m_scopeController->scopeDock(),
            m_scopeController->tuningDock()};
}

QList<QAction*> Bds5Workspace::driveMenuActions() const {
    return m_driveActions->menuActions();
}

void Bds5Workspace::activate(const ConnectionChoice& choice) {
    m_connection->connectTo(choice);
    if (m_connection->isConnected()) emit message(tr("Connected to %1").arg(m_connection->linkDescription()));
}

void Bds5Workspace::deactivate() {
    m_connection->disconnectDrive();
}

bool Bds5Workspace::isConnected() const {
    return m_connection->isConnected();
}

QString Bds5Workspace::statusText() const {
    return m_connection->hasLink() ? m_connection->linkDescription() : tr("No drive");
}

// A serial link's description already names its port and rate ("/dev/ttyUSB0 9600 8N1"); the simulated
// drive's ("Simulated BDS5") gets the rate alone.
QString Bds5Workspace::portText() const {
    const bool simulated = m_connection->choice().kind == ConnectionChoice::Kind::Simulator;
    return m_connection->hasLink() && simulated ? tr("%1 baud").arg(m_connection->choice().baudRate) : QString();
}

QString Bds5Workspace::modeText() const {
    return m_connection->isConnected() && !m_mode.isEmpty() ? m_mode : tr("Mode: \u2014");
}

FamilyWorkspace::LinkState Bds5Workspace::linkState() const {
    using State = serialport::Bds5Session::State;
    if (!m_connection->isConnected() || !m_connection->session()) return {tr("Disconnected"), QStringLiteral("#b3261e")};
    switch (m_connection->session()->state()) {
    case State::Closed: break;
    case State::WaitingForPrompt: return {tr("Connected"), QStringLiteral("#c77700")};
    case State::Ready: return {tr("Ready"), QStringLiteral("#1e8e3e")};
    case State::Busy: return {tr("Busy"), QStringLiteral("#1a73e8")};
    }
    return {tr("Disconnected"), QStringLiteral("#b3261e")};
}

serialport::DriveSession* Bds5Workspace::driveSession() const {
    return m_connection->isConnected() ? m_connection->driveSession() : nullptr;
}

serialport::Link* Bds5Workspace::link() const {
    return m_connection->isConnected() ? m_connection->link() : nullptr;
}

ErrorSource* Bds5Workspace::errorSource() const {
    return m_errors;
}

QString Bds5Workspace::busyReason() const {
    return SessionHost::of(*m_connection).busyReason();
}

QString Bds5Workspace::sampleProgram() const {
    return resources::kSampleProgram;
}

bool Bds5Workspace::typeIntoTerminal(const QByteArray& bytes, bool urgent) {
    if (urgent) m_connection->sendUrgent(bytes);
    else m_connection->sendRaw(bytes);
    return true;
}

} // namespace app
