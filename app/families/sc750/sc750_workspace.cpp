// Sc750Workspace: link and session lifetime, the Motion Dialogue menus, editor hooks and the status line.
#include "sc750_workspace.h"

#include "app/tuning/tuning_panel.h"

#include "families/sc750/sc750_error_source.h"

#include "sc750_controller_menu.h"
#include "sc750_debugger.h"
#include "sc750_function_dialog.h"
#include "sc750_output_dock.h"
#include "sc750_status_display.h"
#include "sc750_variables_dock.h"

#include "editor_area.h"
#include "editor_tabs.h"
#include "file_types.h"
#include "main_window.h"
#include "serialport/sc750_drive_session.h"
#include "scope/session_watch_source.h"
#include "scope/watch_view.h"
#include "terminal_dock.h"

#include "editor/program_editor.h"
#include "editor/servobasic_language.h"
#include "resources/resources.h"

#include <QAction>
#include <QKeyEvent>
#include <QLabel>
#include <QMenu>
#include <QStatusBar>
#include <QStyle>

#include <utility>

namespace app {

Sc750Workspace::Sc750Workspace(MainWindow& mainWindow)
    : SessionWorkspace(mainWindow, drive_core::DriveFamily::Sc750), m_debugger(new Sc750Debugger(*this)),
      m_output(new Sc750OutputDock(&mainWindow)), m_variables(new Sc750VariablesDock(*this, &mainWindow)) {
    createMenus();
    m_errors = new Sc750ErrorSource(*this);
    m_cursorLabel = new QLabel(&mainWindow);
    m_cursorLabel->setObjectName(QStringLiteral("sc750CursorLabel"));
    m_cursorLabel->setToolTip(tr("Motion Dialogue's status line: the axis and the cursor's line and column"));
    m_cursorLabel->setContentsMargins(6, 0, 6, 0);
    m_cursorLabel->hide();
    m_display = new Sc750StatusDisplay(*this, &mainWindow);
    m_display->hide();
    mainWindow.statusBar()->addPermanentWidget(m_display);
    mainWindow.statusBar()->addPermanentWidget(m_cursorLabel);

    connect(m_debugger, &Sc750Debugger::message, this, &FamilyWorkspace::message);
    connect(m_debugger, &Sc750Debugger::stateChanged, this, [this] {
        updateActions();
        m_variables->setWritable(!m_debugger->running());
        emit statusChanged();
    });
    connect(m_debugger, &Sc750Debugger::runStarted, this, [this] {
        m_output->clear();
        m_output->show();
        m_output->raise();
    });
    connect(m_output, &Sc750OutputDock::stopRequested, this, [this] {
        if (m_debugger->state() == Sc750Debugger::State::Running) m_debugger->stop();
    });
    connect(m_output, &Sc750OutputDock::inputTyped, this, [this](const QByteArray& bytes) {
        if (isConnected()) m_session->sendProgramInput(bytes);
    });
    connect(&mainWindow, &MainWindow::familyChanged, this, [this](drive_core::DriveFamily family) {
        m_shown = family == drive_core::DriveFamily::Sc750;
        if (m_shown && !m_placed) {
            // Motion Dialogue's output window sits under the editor, with the terminal.
            m_placed = true;
            window().addDockWidget(Qt::BottomDockWidgetArea, m_output);
            window().tabifyDockWidget(window().terminalDock(), m_output);
            m_output->hide();
        }
        m_cursorLabel->setVisible(m_shown);
        m_display->setVisible(m_shown);
        updateActions();
        followEditor(window().editor());
    });
    connect(&mainWindow, &MainWindow::currentEditorChanged, this, &Sc750Workspace::followEditor);
    connect(mainWindow.editorArea(), &EditorArea::currentDocumentChanged, this,
            [this] { followEditor(window().editor()); });
    updateActions();
}

Sc750Workspace::~Sc750Workspace() {
    // The window's widgets are going: nothing from the closing link may reach them.
    if (m_session) m_session->disconnect(this);
    m_session = nullptr;
    releaseLink();
}

QList<QMenu*> Sc750Workspace::menus() const {
    return {m_compileMenu, m_optionsMenu};
}

QList<QDockWidget*> Sc750Workspace::docks() const {
    return {m_output, m_variables, tuning().dock};
}

void Sc750Workspace::createMenus() {
    m_compileMenu = new QMenu(tr("&Compile"), &window());
    m_compileMenu->setObjectName(QStringLiteral("sc750CompileMenu"));
    QMenu* menu = m_compileMenu;
    menu->addAction(tr("&Compile Program"), QKeySequence(tr("Ctrl+F9")), m_debugger, &Sc750Debugger::compile);
    menu->addAction(tr("&Run Program"), QKeySequence(tr("Ctrl+R")), m_debugger, &Sc750Debugger::run);
    menu->addAction(tr("R&eset Program"), QKeySequence(tr("Alt+R")), m_debugger, &Sc750Debugger::reset);
    // F5 (L2661); F8 is the manual's other key for it (L2732).
    QAction* cont = menu->addAction(tr("Co&ntinue Program"), m_debugger, &Sc750Debugger::continueProgram);
    cont->setShortcuts({QKeySequence(Qt::Key_F5), QKeySequence(Qt::Key_F8)});
    // Ctrl C (L2692) is also Copy: the editor and the output window take it as Stop only while a program
    // runs and no text is selected (eventFilter, Sc750OutputDock::stopRequested), so it is shown in the
    // menu but is not the action's shortcut (that would be ambiguous with Copy); Ctrl+Break works anywhere.
    QAction* stop = menu->addAction(tr("&Stop Program\tCtrl+C"), m_debugger, &Sc750Debugger::stop);
    stop->setShortcut(QKeySequence(tr("Ctrl+Break")));
    menu->addSeparator();
    QAction* output = menu->addAction(tr("&Output Window"), QKeySequence(Qt::Key_F4), this, [this] {
        m_output->setVisible(!m_output->isVisible() || !m_output->hasFocus());
        if (m_output->isVisible()) m_output->focusInput();
    });
    output->setObjectName(QStringLiteral("sc750OutputAction"));
    menu->addAction(tr("Set &Breakpoint"), QKeySequence(Qt::Key_F9), m_debugger, &Sc750Debugger::toggleBreakpoint);
    menu->addAction(tr("Clear &All Breakpoints"), m_debugger, &Sc750Debugger::clearBreakpoints);
    menu->addAction(tr("&Variables..."), this, [this] {
        m_variables->show();
        m_variables->raise();
        m_variables->focusName();
    });
    menu->addAction(tr("Variab&le Browser"), this, [this] { m_variables->showAllVariables(); })
        ->setStatusTip(tr("Every predefined variable and parameter, grouped, with live values"));
    menu->addAction(tr("Real &Time Function Call..."), this, &Sc750Workspace::showFunctionCall);
    menu->addAction(tr("&Watch Variables..."), this, &Sc750Workspace::watchVariables)
        ->setStatusTip(tr("A rolling chart of POSITION, VELOCITY, POS.ERROR... read while the program runs"));
    menu->addAction(tuning().action); // the gains, a test move and DACMON on the bench's oscilloscope
    m_optionsMenu = new Sc750ControllerMenu(*this, &window());
    const QStyle* style = window().style();
    action(QStringLiteral("Run Program"))->setIcon(style->standardIcon(QStyle::SP_MediaPlay));
    action(QStringLiteral("Stop Program"))->setIcon(style->standardIcon(QStyle::SP_MediaStop));
    action(QStringLiteral("Stop Program"))->setIconText(tr("Stop")); // the menu's text carries "\tCtrl+C"
    action(QStringLiteral("Continue Program"))->setIcon(style->standardIcon(QStyle::SP_MediaSeekForward));
}

QList<QAction*> Sc750Workspace::toolBarActions() const {
    return {action(QStringLiteral("Compile Program")), action(QStringLiteral("Run Program")),
            action(QStringLiteral("Stop Program")),    action(QStringLiteral("Continue Program")),
            nullptr,                                   action(QStringLiteral("Set Breakpoint"))};
}

QString Sc750Workspace::busyReason() const {
    return m_debugger->state() == Sc750Debugger::State::Downloading ? tr("a download is under way") : QString();
}

QAction* Sc750Workspace::action(const QString& text) const {
    for (QMenu* menu : menus())
        for (QAction* a : menu->actions()) {
            QString name = a->text().section(QLatin1Char('\t'), 0, 0);
            name.remove(QLatin1Char('&'));
            if (name.endsWith(QLatin1String("..."))) name.chop(3);
            if (name == text) return a;
        }
    return nullptr;
}

QWidget* Sc750Workspace::showFunctionCall() {
    auto* dialog = new Sc750FunctionDialog(*this, &window());
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->open();
    return dialog;
}

void Sc750Workspace::sessionCreated(serialport::DriveSession& session) {
    m_session = &static_cast<serialport::Sc750DriveSession&>(session).sc750();
    // One axis of a line: the AxisLink logs it on; the axis shown (and logged on again after a reconnection)
    // is that one, not the RS-232 address 255. A later plain link goes back to 255, which a lone SC750 on
    // RS-232 answers to.
    if (!lineAxis().isEmpty()) {
        m_axis = qBound(0, lineAxis().toInt(), 255);
        m_axisFromLine = true;
    } else if (std::exchange(m_axisFromLine, false)) {
        m_axis = 255;
    }
    showCursorStatus();
    connect(m_session, &serialport::Sc750Session::finished, this,
            [this](quint64 id, const serialport::Sc750Reply& reply) {
                const auto handlers = m_waiting.take(id);
                if (handlers.first) handlers.first(reply);
            });
    connect(m_session, &serialport::Sc750Session::failed, this, [this](quint64 id, const QString& why) {
        const auto handlers = m_waiting.take(id);
        if (handlers.second) handlers.second(why);
        else emit message(tr("SC750: %1").arg(why));
    });
    connect(m_session, &serialport::Sc750Session::programOutput, m_output, &Sc750OutputDock::display);
}

void Sc750Workspace::sessionOpened() {
    m_debugger->attachSession();
    if (m_axis != 255) m_session->logOn(m_axis);
    send('V', {}, [this](const serialport::Sc750Reply& reply) {
        const QStringList parts = reply.payload.split(QLatin1Char(','));
        if (parts.size() >= 2) setLinkText(tr("SC%1, firmware %2").arg(parts[0], parts[1]));
        m_display->setModel(parts.value(0));
        emit statusChanged();
    });
    send('?', {}, [this](const serialport::Sc750Reply& reply) { m_debugger->adoptDriveStatus(reply.payload); });
}

void Sc750Workspace::sessionEnding() {
    m_waiting.clear();
    m_session->disconnect(this);
    m_session = nullptr;
    m_debugger->attachSession(); // to none
}

void Sc750Workspace::setAxis(int axis) {
    m_axis = qBound(0, axis, 255);
    if (isConnected() && m_axis != 255) m_session->logOn(m_axis);
    showCursorStatus();
    emit statusChanged();
}

ErrorSource* Sc750Workspace::errorSource() const {
    return m_errors;
}

QString Sc750Workspace::sampleProgram() const {
    return resources::kSc750SampleProgram;
}

QString Sc750Workspace::statusText() const {
    if (isReconnecting())
        return tr("SC750 axis %1 on %2: connection lost, reconnecting\u2026").arg(m_axis).arg(linkText());
    if (!isConnected()) return tr("SC750 axis %1, not connected").arg(m_axis);
    // The axis is in the cursor label beside it ("Axis 255 Line ..."): not said twice, so the status bar
    // keeps room for messages such as "Breakpoint at line 12".
    return tr("%1, %2 \u2014 %3").arg(linkText(), m_debugger->stateText(), link()->description());
}

bool Sc750Workspace::send(char letter, const QString& payload, Done done, Failed failed) {
    if (!isConnected()) {
        if (failed) failed(tr("not connected"));
        else emit message(tr("Not connected to an SC750: choose Drive > Connect..."));
        return false;
    }
    m_waiting.insert(m_session->send(letter, payload), {std::move(done), std::move(failed)});
    return true;
}

void Sc750Workspace::updateActions() {
    using State = Sc750Debugger::State;
    const State state = m_debugger->state();
    const bool on = m_shown && isConnected();
    const bool idle = on && !m_debugger->running();
    for (QAction* a : m_compileMenu->actions()) a->setEnabled(on);
    action(QStringLiteral("Compile Program"))->setEnabled(m_shown);
    action(QStringLiteral("Set Breakpoint"))->setEnabled(m_shown);
    action(QStringLiteral("Clear All Breakpoints"))->setEnabled(m_shown);
    action(QStringLiteral("Output Window"))->setEnabled(m_shown);
    action(QStringLiteral("Variables"))->setEnabled(m_shown);
    // During a download too: Ctrl C stops motion and the download (no frame goes out after it).
    action(QStringLiteral("Stop Program"))->setEnabled(on && (state == State::Running || state == State::Downloading));
    action(QStringLiteral("Continue Program"))->setEnabled(on && (state == State::Stopped || state == State::AtBreakpoint));
    action(QStringLiteral("Real Time Function Call"))->setEnabled(idle);
    for (QAction* a : m_optionsMenu->actions()) a->setEnabled(m_shown);
    showCursorStatus();
}

void Sc750Workspace::followEditor(editor::ProgramEditor* editor) {
    if (!editor) return;
    const bool basic = fileTypeOf(window().editorArea()->tabs()->displayName(editor)) == FileType::Sc750Program;
    if (basic) editor::ServoBasicLanguage::install(*editor);
    else editor::ServoBasicLanguage::uninstall(*editor);
    if (m_editor != editor) {
        if (m_editor) m_editor->disconnect(this);
        m_editor = editor;
        connect(editor, &QsciScintilla::cursorPositionChanged, this, &Sc750Workspace::showCursorStatus);
        editor->installEventFilter(this);
    }
    showCursorStatus();
}

void Sc750Workspace::showCursorStatus() {
    if (!m_shown || !m_editor) return;
    int line = 0, index = 0;
    m_editor->getCursorPosition(&line, &index);
    m_cursorLabel->setText(tr("Axis %1  Line %2 Col %3")
                               .arg(m_axis, 3, 10, QLatin1Char('0'))
                               .arg(line + 1, 4, 10, QLatin1Char('0'))
                               .arg(index + 1, 2, 10, QLatin1Char('0')));
}

bool Sc750Workspace::eventFilter(QObject* watched, QEvent* event) {
    // Ctrl C stops a running program (L2692) unless the user is copying a selection.
    if (m_shown && watched == m_editor && (event->type() == QEvent::ShortcutOverride || event->type() == QEvent::KeyPress)) {
        const auto* key = static_cast<QKeyEvent*>(event);
        if (key->key() == Qt::Key_C && key->modifiers() == Qt::ControlModifier && !m_editor->hasSelectedText() &&
            m_debugger->state() == Sc750Debugger::State::Running) {
            event->accept();
            if (event->type() == QEvent::KeyPress) m_debugger->stop();
            return true;
        }
    }
    return FamilyWorkspace::eventFilter(watched, event);
}

} // namespace app
