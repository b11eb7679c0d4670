// MainWindow: composition and wiring.
#include "main_window.h"

#include "machine/axes_dock.h"
#include "status_bar_room.h"
#include "drive/terminal_tabs.h"

#include "connection_dialog.h"
#include "families/bds5/debug_highlighter.h"
#include "document_controller.h"
#include "editor_area.h"
#include "family_workspace.h"
#include "help_browser.h"
#include "options_controller.h"
#include "terminal_dock.h"
#include "terminal_widget.h"
#include "families/bds5/bds5_workspace.h"
#include "errors/error_log_dock.h"
#include "errors/error_source.h"
#include "errors/program_line_jump.h"
#include "families/sc750/sc750_workspace.h"
#include "families/pmc960/pmc960_workspace.h"

#include "editor/diagnostics_status.h"
#include "editor/keymap.h"
#include "editor/outline_dock.h"
#include "editor/program_editor.h"
#include "resources/resources.h"

#include <QApplication>
#include <QCloseEvent>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QScreen>
#include <QSettings>
#include <QStatusBar>
#include <QToolBar>

namespace app {

namespace {
constexpr int kStatusMessageMs = 10000;
constexpr double kTerminalShare = 0.30; // of the window height, on first show: the program comes first
constexpr QSize kDefaultSize(1280, 800); // on a screen that has room for it; a 1366×768 laptop gets 1280×704
} // namespace

MainWindow::MainWindow(drive_core::DriveFamily family, QWidget* parent)
    : QMainWindow(parent), m_editorArea(new EditorArea(this)), m_terminalDock(new TerminalDock(this)),
      m_bds5(new Bds5Workspace(*this)), m_documents(m_editorArea->documents()) {
    resources::initialize();
    setObjectName(QStringLiteral("mainWindow"));
    resizeToFitScreen();
    setCentralWidget(m_editorArea);
    addDockWidget(Qt::BottomDockWidgetArea, m_terminalDock);

    createDocks();
    createMenus();
    createStatusBar();
    TerminalWidget* term = terminal();
    connect(term, &TerminalWidget::bytesTyped, this, [this](const QByteArray& b) { typeIntoTerminal(b, false); });
    connect(term, &TerminalWidget::urgentBytesTyped, this, [this](const QByteArray& b) { typeIntoTerminal(b, true); });
    m_bds5->build();
    addWorkspace(m_bds5);                    // Motion Link for the BDS5
    addWorkspace(new Sc750Workspace(*this)); // issue 8: Motion Dialogue for the SC750
    addWorkspace(new Pmc960Workspace(*this)); // issue 9: MPL menu, status panel, parameter table
    connect(m_documents, &DocumentController::documentChanged, this, &MainWindow::updateTitle);
    connect(m_documents, &DocumentController::statusMessage, this,
            [this](const QString& message) { statusBar()->showMessage(message, kStatusMessageMs); });
    connect(m_editorArea, &EditorArea::currentDocumentChanged, this, &MainWindow::updateTitle);
    connect(m_editorArea, &EditorArea::currentEditorChanged, this, &MainWindow::currentEditorChanged);
    connect(m_editorArea, &EditorArea::currentEditorChanged, this, &MainWindow::followEditor);
    connect(m_editorArea, &EditorArea::statusMessage, this,
            [this](const QString& message) { statusBar()->showMessage(message, kStatusMessageMs); });
    // Options > Editor keys switches the editor's keymap at once, and keeps editor/keymap in step.
    connect(m_optionsController, &OptionsController::optionsChanged, this, [this](const AppOptions& options) {
        const bool classic = options.keymap == AppOptions::Keymap::Classic;
        QSettings().setValue(editor::Keymap::kSettingsKey, classic ? editor::Keymap::kClassic : editor::Keymap::kModern);
        m_editorArea->reloadKeymap();
    });

    openSampleProgram(family);
    followEditor(editor());
    updateTitle();
    terminal()->setFocus();
}

MainWindow::~MainWindow() = default;

editor::ProgramEditor* MainWindow::editor() const {
    return m_editorArea->currentEditor();
}

TerminalWidget* MainWindow::terminal() const {
    return m_terminalDock->terminal();
}

DriveConnection& MainWindow::connection() const {
    return m_bds5->connection();
}
DriveActions& MainWindow::driveActions() const {
    return m_bds5->driveActions();
}
ProgramController& MainWindow::programController() const {
    return m_bds5->programController();
}
ScopeController& MainWindow::scopeController() const {
    return m_bds5->scopeController();
}

void MainWindow::connectDrive(const ConnectionChoice& choice) {
    m_axis = choice.line ? choice.axis : QString();
    m_axisLine = choice.line;
    updateTitle();
    FamilyWorkspace* next = workspace(choice.family);
    if (!next) {
        showLinkError(tr("This build of ServoDesk has no %1 support.").arg(ConnectionChoice::familyName(choice.family)));
        return;
    }
    for (FamilyWorkspace* w : m_workspaces)
        if (w != next) w->deactivate(); // one family on the port at a time
    showFamily(choice.family);
    // The terminal is shared by the families: a line says where what follows comes from.
    const QString where = choice.kind == ConnectionChoice::Kind::Simulator
                              ? choice.portText()
                              : tr("%1 on %2").arg(ConnectionChoice::familyName(choice.family), choice.portText());
    terminal()->displayNotice(tr("Connecting to %1").arg(where));
    next->activate(choice);
    updateLinkStatus();
}

ConnectionDialog* MainWindow::showConnectionDialog() {
    auto* dialog = new ConnectionDialog(this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog] { connectDrive(dialog->choice()); });
    dialog->open();
    return dialog;
}

void MainWindow::addWorkspace(FamilyWorkspace* workspace) {
    workspace->setParent(this);
    m_workspaces.append(workspace);
    for (QMenu* menu : workspace->menus()) {
        menuBar()->insertMenu(m_driveMenu->menuAction(), menu);
        menu->menuAction()->setVisible(false);
    }
    for (QDockWidget* dock : workspace->docks()) {
        if (dockWidgetArea(dock) == Qt::NoDockWidgetArea) { // not placed by the workspace itself
            addDockWidget(Qt::RightDockWidgetArea, dock);
            dock->hide();
        }
        m_viewMenu->addAction(dock->toggleViewAction());
    }
    for (QToolBar* bar : workspace->toolBars()) {
        addToolBar(bar);
        m_familyToolBars.insert(workspace, bar);
    }
    if (const QList<QAction*> items = workspace->driveMenuActions(); !items.isEmpty()) {
        for (QAction* item : items) {
            QAction* added = item ? item : m_driveMenu->addSeparator();
            if (item) m_driveMenu->addAction(item);
            m_familyDriveItems.insert(workspace, added);
        }
    }
    if (const QList<QAction*> actions = workspace->toolBarActions(); !actions.isEmpty()) {
        auto* bar = new QToolBar(ConnectionChoice::familyName(workspace->family()), this);
        bar->setObjectName(ConnectionChoice::familyKey(workspace->family()) + QStringLiteral("ToolBar"));
        bar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
        for (QAction* action : actions) {
            if (action) bar->addAction(action);
            else bar->addSeparator();
        }
        addToolBar(bar);
        bar->hide();
        m_familyToolBars.insert(workspace, bar);
    }
    if (ErrorSource* errors = workspace->errorSource()) m_errorLogDock->addSource(errors);
    connect(workspace, &FamilyWorkspace::statusChanged, this, &MainWindow::updateLinkStatus);
    connect(workspace, &FamilyWorkspace::message, this, &MainWindow::showLinkError);
    connect(workspace, &FamilyWorkspace::terminalReceived, this, [this, workspace](const QByteArray& bytes) {
        if (workspace == this->workspace(m_family)) terminal()->displayBytes(bytes);
    });
    showFamily(m_family);
    updateLinkStatus(); // "No drive" before any connection
}

FamilyWorkspace* MainWindow::workspace(drive_core::DriveFamily family) const {
    // The last one added for a family wins (a test or a plug-in may stand in for the built-in one).
    for (auto it = m_workspaces.crbegin(); it != m_workspaces.crend(); ++it)
        if ((*it)->family() == family) return *it;
    return nullptr;
}

void MainWindow::showFamily(drive_core::DriveFamily family) {
    if (m_axesDock) m_axesDock->followFamily(family);
    for (auto it = m_familyToolBars.cbegin(); it != m_familyToolBars.cend(); ++it) {
        it.value()->setVisible(it.key() == workspace(family));
        it.value()->toggleViewAction()->setVisible(it.key() == workspace(family));
    }
    for (auto it = m_familyDriveItems.cbegin(); it != m_familyDriveItems.cend(); ++it)
        it.value()->setVisible(it.key() == workspace(family));
    for (FamilyWorkspace* w : m_workspaces) {
        const bool active = w == workspace(family);
        for (QMenu* menu : w->menus()) menu->menuAction()->setVisible(active);
        for (QDockWidget* dock : w->docks()) {
            dock->toggleViewAction()->setVisible(active);
            if (!active) dock->hide(); // it would talk to a session that is not there
        }
    }
    m_errorLogDock->setFamily(family); // the one Error Log shows the chosen family's errors
    if (m_family == family) return;
    m_family = family;
    emit familyChanged(family);
}

// Each family opens with a program in its own language: hello.bds in front of an SC750 compiles to errors.
void MainWindow::openSampleProgram(drive_core::DriveFamily family) {
    const FamilyWorkspace* w = workspace(family);
    const QString sample = w && !w->sampleProgram().isEmpty() ? w->sampleProgram() : resources::kSampleProgram;
    m_documents->openTemplate(sample, QFileInfo(sample).fileName());
}

void MainWindow::disconnectActive() {
    if (FamilyWorkspace* w = workspace(m_family)) w->deactivate();
    m_axis.clear();
    m_axisLine.reset();
    updateTitle();
    updateLinkStatus();
}

void MainWindow::restoreLayout() {
    QSettings settings;
    m_layoutRestored = restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray());
    restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
}

void MainWindow::createMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    m_editorArea->fillFileMenu(file);
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);
    m_editorArea->fillEditMenu(menuBar()->addMenu(tr("&Edit")));
    QMenu* search = menuBar()->addMenu(tr("&Search"));
    m_editorArea->fillSearchMenu(search);
    search->addAction(m_outlineDock->goToLabelAction());

    // The families' menus go here, before Drive (addWorkspace).
    QMenu* drive = m_driveMenu = menuBar()->addMenu(tr("&Drive"));
    drive->addAction(tr("&Connect..."), QKeySequence(tr("Ctrl+K")), this, &MainWindow::showConnectionDialog);
    m_disconnectAction = drive->addAction(tr("&Disconnect"), this, &MainWindow::disconnectActive);

    QMenu* machine = menuBar()->addMenu(tr("Mach&ine"));
    QAction* axesPanel = m_axesDock->toggleViewAction();
    axesPanel->setText(tr("&Axes Panel"));
    axesPanel->setShortcut(QKeySequence(tr("Ctrl+Shift+A")));
    machine->addAction(axesPanel);
    connect(axesPanel, &QAction::triggered, m_axesDock, [this](bool shown) {
        if (shown) m_axesDock->raise(); // in front of the Outline it shares a tab with
    });
    machine->addSeparator();
    for (QAction* a : m_axesDock->menuActions()) {
        machine->addAction(a);
        connect(a, &QAction::triggered, m_axesDock, [this] { m_axesDock->show(); m_axesDock->raise(); });
    }

    QMenu* view = m_viewMenu = menuBar()->addMenu(tr("&View"));
    QAction* toggleTerminal = m_terminalDock->toggleViewAction();
    toggleTerminal->setShortcut(QKeySequence(tr("Ctrl+Shift+T")));
    view->addAction(toggleTerminal);
    view->addAction(m_helpBrowser->toggleViewAction());
    view->addAction(m_outlineDock->toggleViewAction());
    view->addAction(terminalTabAction(*this, m_terminalDock, m_errorLogDock, m_errorLogDock->windowTitle(), this));
    view->addSeparator(); // the active family's docks follow (addWorkspace)
    m_optionsController->addToMenu(menuBar()->addMenu(tr("&Options")));

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    // Motion Dialogue's Help menu (Index, General, Editor Commands, About) for every family: the reference
    // and the introduction follow the family chosen in Drive > Connect.
    QAction* reference = help->addAction(tr("BDS5 &Reference"), this, [this] {
        if (const FamilyWorkspace* w = workspace(m_family)) m_helpBrowser->showTopic(w->referenceTopic());
    });
    connect(this, &MainWindow::familyChanged, this, [this, reference](drive_core::DriveFamily family) {
        m_helpBrowser->setFamily(family);
        reference->setText(tr("%1 &Reference").arg(ConnectionChoice::familyName(family)));
    });
    help->addAction(tr("&Introduction"), this, [this] { m_helpBrowser->showTopic(QStringLiteral("intro")); });
    help->addAction(tr("Classic Editor &Keys"), m_editorArea, &EditorArea::showClassicKeys);
    help->addSeparator();
    help->addAction(tr("&About ServoDesk"), this, &MainWindow::showAbout);
}

void MainWindow::createDocks() {
    m_debugHighlighter = new DebugHighlighter(*this, this);
    m_optionsController = new OptionsController(*this, *m_debugHighlighter);
    m_helpBrowser = new HelpBrowser(this);
    addDockWidget(Qt::RightDockWidgetArea, m_helpBrowser);
    m_helpBrowser->hide();
    m_outlineDock = new editor::OutlineDock(this); // labels and tasks of the current program, Go to label
    addDockWidget(Qt::RightDockWidgetArea, m_outlineDock);
    m_errorLogDock = new ErrorLogDock(this);
    addDockWidget(Qt::BottomDockWidgetArea, m_errorLogDock);
    m_errorLogDock->hide();
    m_axesDock = new AxesDock(this); // issue 21: a multidrop line's axes, hidden until asked for
    addDockWidget(Qt::RightDockWidgetArea, m_axesDock);
    tabifyDockWidget(m_outlineDock, m_axesDock); // the whole height for the table; the Outline a tab away
    m_axesDock->hide();
    connect(m_axesDock, &AxesDock::axisChosen, this, &MainWindow::connectDrive);
    connect(m_axesDock, &AxesDock::lineNeeded, this, [this](const std::shared_ptr<serialport::Link>& line) {
        if (m_axisLine && m_axisLine == line) { // one conversation at a time on a line
            terminal()->displayNotice(tr("Left axis %1: the Axes panel needs the line").arg(m_axis));
            disconnectActive();
        }
    });
    connect(m_errorLogDock, &ErrorLogDock::goToProgramLine, this,
            [this](int driveLine) { ProgramLineJump::show(*editor(), driveLine); });
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
    m_editorArea->installStatusWidgets(statusBar());
    m_diagnosticsStatus = new editor::DiagnosticsStatus(this); // the drive's errors in the current program
    statusBar()->insertPermanentWidget(0, m_diagnosticsStatus);
    const auto* editorCell = statusBar()->findChild<QLabel*>(QStringLiteral("editorSizeLabel"));
    new StatusBarRoom(*statusBar(), {editorCell ? editorCell->parentWidget() : nullptr, m_portLabel->parentWidget(),
                                     m_modeLabel->parentWidget()});
    updateLinkStatus();
}

// The terminal talks to the active family when it has a terminal (the BDS5, the PMC-960). The SC750's
// program I/O has Motion Dialogue's Output window instead; typing here says so once.
void MainWindow::typeIntoTerminal(const QByteArray& bytes, bool urgent) {
    FamilyWorkspace* active = workspace(m_family);
    if (!active || active->typeIntoTerminal(bytes, urgent) || m_terminalHintShown == m_family) return;
    m_terminalHintShown = m_family;
    terminal()->displayNotice(tr("The %1 has no terminal: its program's PRINT and INPUT are in the Output window "
                                 "(F4).")
                                  .arg(ConnectionChoice::familyName(m_family)));
}

void MainWindow::followEditor(editor::ProgramEditor* current) {
    m_outlineDock->setEditor(current);
    m_diagnosticsStatus->setEditor(current);
    // F1 in the editor shows a popup and opens the reference at the same topic.
    if (current)
        connect(current, &editor::ProgramEditor::helpRequested, m_helpBrowser, &HelpBrowser::showTopic,
                Qt::UniqueConnection);
}

void MainWindow::updateTitle() {
    if (m_axis.isEmpty())
        setWindowTitle(tr("%1[*] \u2014 ServoDesk").arg(m_documents->displayName()));
    else
        setWindowTitle(tr("%1[*] \u2014 axis %2 \u2014 ServoDesk").arg(m_documents->displayName(), m_axis));
    setWindowModified(editor() && editor()->isModified());
}

void MainWindow::updateLinkStatus() {
    const FamilyWorkspace* w = workspace(m_family);
    if (!w) return;
    m_linkLabel->setText(w->statusText());
    const QString port = w->portText();
    m_portLabel->setText(port);
    m_portLabel->parentWidget()->setVisible(!port.isEmpty());
    const QString mode = w->modeText();
    m_modeLabel->setText(mode);
    m_modeLabel->parentWidget()->setVisible(!mode.isEmpty());
    m_disconnectAction->setEnabled(w->isConnected());
    const FamilyWorkspace::LinkState state = w->linkState();
    m_stateLabel->setText(
        QStringLiteral("<span style=\"color:%1\">\u25cf</span> %2").arg(state.colour, state.text.toHtmlEscaped()));
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
                    "debug programs for the Kollmorgen BDS5, the Pacific Scientific SC750 and the ORMEC "
                    "PMC-960, on a serial port or against the built-in simulated drives.</p>")
                     .arg(QApplication::applicationVersion()));
    box->open();
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (m_editorArea->hasUnsavedChanges() && !m_closeConfirmed) {
        event->ignore();
        m_editorArea->whenSafeToClose([this] {
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

// A laptop's 1366×768 (or 1024×768) screen is smaller than the default size: a window taller than the screen
// hides its status bar below the edge. Room is left for a window manager's title bar and a panel.
void MainWindow::resizeToFitScreen() {
    const QScreen* where = screen();
    if (!where) {
        resize(kDefaultSize);
        return;
    }
    const QSize room = where->availableGeometry().size() - QSize(16, 64);
    resize(kDefaultSize.boundedTo(room).expandedTo(QSize(640, 480)));
}

void MainWindow::showEvent(QShowEvent* event) {
    QMainWindow::showEvent(event);
    if (m_shownOnce) return;
    m_shownOnce = true;
    if (!m_layoutRestored) resizeDocks({m_terminalDock}, {int(height() * kTerminalShare)}, Qt::Vertical);
}

} // namespace app
