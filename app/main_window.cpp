// MainWindow: composition and wiring.
#include "main_window.h"

#include "connection_dialog.h"
#include "document_controller.h"
#include "drive_connection.h"
#include "terminal_dock.h"
#include "terminal_widget.h"

#include "editor/bds5_lexer.h"
#include "editor/program_editor.h"
#include "resources/resources.h"
#include "serialport/bds5_protocol.h"

#include <QApplication>
#include <QCloseEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>

namespace app {

namespace {
constexpr int kStatusMessageMs = 10000;
constexpr double kTerminalShare = 0.40; // of the window height, on first show
} // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), m_editor(new editor::ProgramEditor(this)), m_terminalDock(new TerminalDock(this)),
      m_connection(new DriveConnection(this)), m_documents(new DocumentController(*m_editor, this)) {
    resources::initialize();
    setObjectName(QStringLiteral("mainWindow"));
    resize(1200, 800);
    m_editor->setLanguageLexer(new editor::Bds5Lexer);
    setCentralWidget(m_editor);
    addDockWidget(Qt::BottomDockWidgetArea, m_terminalDock);

    createMenus();
    createStatusBar();
    wireConnection();
    connect(m_documents, &DocumentController::documentChanged, this, &MainWindow::updateTitle);
    connect(m_documents, &DocumentController::statusMessage, this,
            [this](const QString& message) { statusBar()->showMessage(message, kStatusMessageMs); });
    connect(m_editor, &QsciScintilla::modificationChanged, this, &MainWindow::setWindowModified);

    m_documents->openTemplate(resources::kSampleProgram, QStringLiteral("hello.bds"));
    updateTitle();
    terminal()->setFocus();
}

MainWindow::~MainWindow() = default;

TerminalWidget* MainWindow::terminal() const {
    return m_terminalDock->terminal();
}

void MainWindow::connectDrive(const ConnectionChoice& choice) {
    m_connection->connectTo(choice);
    if (m_connection->isConnected())
        terminal()->displayNotice(tr("Connected to %1").arg(m_connection->linkDescription()));
}

ConnectionDialog* MainWindow::showConnectionDialog() {
    auto* dialog = new ConnectionDialog(this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog] { connectDrive(dialog->choice()); });
    dialog->open();
    return dialog;
}

void MainWindow::restoreLayout() {
    QSettings settings;
    m_layoutRestored = restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray());
    restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
}

void MainWindow::createMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&New"), QKeySequence::New, m_documents, &DocumentController::newDocument);
    file->addAction(tr("&Open..."), QKeySequence::Open, m_documents, &DocumentController::open);
    file->addAction(tr("&Save"), QKeySequence::Save, m_documents, &DocumentController::save);
    file->addAction(tr("Save &As..."), QKeySequence::SaveAs, m_documents, &DocumentController::saveAs);
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

    QMenu* drive = menuBar()->addMenu(tr("&Drive"));
    drive->addAction(tr("&Connect..."), QKeySequence(tr("Ctrl+K")), this, &MainWindow::showConnectionDialog);
    m_disconnectAction = drive->addAction(tr("&Disconnect"), m_connection, &DriveConnection::disconnectDrive);

    QMenu* view = menuBar()->addMenu(tr("&View"));
    QAction* toggleTerminal = m_terminalDock->toggleViewAction();
    toggleTerminal->setShortcut(QKeySequence(tr("Ctrl+Shift+T")));
    view->addAction(toggleTerminal);

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About ServoDesk"), this, &MainWindow::showAbout);
}

void MainWindow::createStatusBar() {
    // Each label sits in a cell with the separator before it, so hiding the cell hides both.
    auto makeLabel = [this](const QString& name, const QString& tip) {
        auto* cell = new QWidget(this);
        auto* layout = new QHBoxLayout(cell);
        layout->setContentsMargins(0, 0, 0, 0);
        if (!statusBar()->findChildren<QLabel*>().isEmpty()) {
            auto* separator = new QFrame(cell);
            separator->setFrameStyle(QFrame::VLine | QFrame::Sunken);
            layout->addWidget(separator);
        }
        auto* label = new QLabel(cell);
        label->setObjectName(name);
        label->setToolTip(tip);
        label->setContentsMargins(6, 0, 6, 0);
        layout->addWidget(label);
        statusBar()->addPermanentWidget(cell);
        return label;
    };
    m_linkLabel = makeLabel(QStringLiteral("linkLabel"), tr("The drive ServoDesk talks to"));
    m_portLabel = makeLabel(QStringLiteral("portLabel"), tr("Port and baud rate"));
    m_modeLabel = makeLabel(QStringLiteral("modeLabel"), tr("The drive's mode, from its last prompt"));
    m_stateLabel = makeLabel(QStringLiteral("stateLabel"), tr("Connection state"));
    updateLinkStatus();
}

void MainWindow::wireConnection() {
    TerminalWidget* term = terminal();
    connect(term, &TerminalWidget::bytesTyped, m_connection, &DriveConnection::sendRaw);
    connect(m_connection, &DriveConnection::rawReceived, term, &TerminalWidget::displayBytes);
    connect(m_connection, &DriveConnection::modeChanged, this, &MainWindow::showMode);
    connect(m_connection, &DriveConnection::linkChanged, this, &MainWindow::updateLinkStatus);
    connect(m_connection, &DriveConnection::connectedChanged, this, &MainWindow::updateLinkStatus);
    connect(m_connection, &DriveConnection::connectedChanged, this, [this](bool connected) {
        if (!connected)
            terminal()->displayNotice(tr("Disconnected from %1").arg(m_connection->linkDescription()));
    });
    connect(m_connection, &DriveConnection::sessionStateChanged, this, &MainWindow::showState);
    connect(m_connection, &DriveConnection::errorOccurred, this, &MainWindow::showLinkError);
}

void MainWindow::updateTitle() {
    setWindowTitle(tr("%1[*] \u2014 ServoDesk").arg(m_documents->displayName()));
    setWindowModified(m_editor->isModified());
}

void MainWindow::updateLinkStatus() {
    const bool hasLink = m_connection->hasLink();
    m_linkLabel->setText(hasLink ? m_connection->linkDescription() : tr("No drive"));
    // A serial link's description already names its port and rate ("/dev/ttyUSB0 9600 8N1").
    const bool simulated = m_connection->choice().kind == ConnectionChoice::Kind::Simulator;
    m_portLabel->setText(hasLink ? m_connection->choice().portText() : QString());
    m_portLabel->parentWidget()->setVisible(hasLink && simulated);
    if (!m_connection->isConnected()) m_modeLabel->setText(tr("Mode: \u2014"));
    m_disconnectAction->setEnabled(m_connection->isConnected());
    showState();
}

void MainWindow::showMode(serialport::Bds5Mode mode, const QString& prompt) {
    m_modeLabel->setText(QStringLiteral("%1 %2").arg(serialport::modeName(mode), prompt));
}

void MainWindow::showState() {
    using State = serialport::Bds5Session::State;
    QString text = tr("Disconnected");
    QString colour = QStringLiteral("#b3261e");
    if (m_connection->isConnected() && m_connection->session()) {
        switch (m_connection->session()->state()) {
        case State::Closed:
            break;
        case State::WaitingForPrompt:
            text = tr("Connected");
            colour = QStringLiteral("#c77700");
            break;
        case State::Ready:
            text = tr("Ready");
            colour = QStringLiteral("#1e8e3e");
            break;
        case State::Busy:
            text = tr("Busy");
            colour = QStringLiteral("#1a73e8");
            break;
        }
    }
    m_stateLabel->setText(
        QStringLiteral("<span style=\"color:%1\">\u25cf</span> %2").arg(colour, text.toHtmlEscaped()));
}

void MainWindow::showLinkError(const QString& message) {
    statusBar()->showMessage(message, kStatusMessageMs);
    terminal()->displayNotice(message);
}

void MainWindow::showAbout() {
    auto* box = new QMessageBox(this);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setWindowTitle(tr("About ServoDesk"));
    box->setIconPixmap(QApplication::windowIcon().pixmap(64, 64));
    box->setText(tr("<h3>ServoDesk %1</h3><p>An IDE for programmable servo drives: write, download, run and "
                    "debug programs for the Kollmorgen BDS5, on a serial port or against the built-in "
                    "simulated drive.</p>")
                     .arg(QApplication::applicationVersion()));
    box->open();
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (m_editor->isModified() && !m_closeConfirmed) {
        event->ignore();
        m_documents->whenSafeToDiscard([this] {
            m_closeConfirmed = true;
            close();
        });
        return;
    }
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("window/state"), saveState());
    event->accept();
}

void MainWindow::showEvent(QShowEvent* event) {
    QMainWindow::showEvent(event);
    if (m_shownOnce) return;
    m_shownOnce = true;
    if (!m_layoutRestored) resizeDocks({m_terminalDock}, {int(height() * kTerminalShare)}, Qt::Vertical);
}

} // namespace app
