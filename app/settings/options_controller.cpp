// OptionsController: applying the options and the safe cable disconnect.
#include "options_controller.h"

#include "families/bds5/debug_highlighter.h"
#include "families/bds5/drive_connection.h"
#include "main_window.h"
#include "options_dialog.h"
#include "terminal_widget.h"
#include "theme.h"

#include "editor/program_editor.h"

#include <QAction>
#include <QMenu>

namespace app {

OptionsController::OptionsController(MainWindow& window, DebugHighlighter& highlighter)
    : QObject(&window), m_window(window), m_highlighter(highlighter), m_options(AppOptions::current()) {
    m_wakeUp = new QAction(tr("&Wake Up Axis"), this);
    m_wakeUp->setObjectName(QStringLiteral("wakeUpAxisAction"));
    m_cableDisconnect = new QAction(tr("Cable &Disconnect"), this);
    m_cableDisconnect->setObjectName(QStringLiteral("cableDisconnectAction"));
    m_cableDisconnect->setToolTip(tr("Finish the command in flight, close the port: the cable may then be unplugged"));
    m_reconnect = new QAction(tr("&Reconnect"), this);
    m_reconnect->setObjectName(QStringLiteral("reconnectAction"));
    connect(m_wakeUp, &QAction::triggered, this, &OptionsController::wakeUpAxis);
    connect(m_cableDisconnect, &QAction::triggered, this, &OptionsController::cableDisconnect);
    connect(m_reconnect, &QAction::triggered, this, &OptionsController::reconnect);
    DriveConnection& connection = window.connection();
    connect(&connection, &DriveConnection::connectedChanged, this, &OptionsController::onConnected);
    connect(&connection, &DriveConnection::linkChanged, this, &OptionsController::updateActions);
    connect(&connection, &DriveConnection::sessionStateChanged, this, &OptionsController::closeWhenQuiet);
    connect(&window, &MainWindow::currentEditorChanged, this, [this](editor::ProgramEditor* editor) {
        if (editor) Theme::applyToEditor(*editor, m_options.theme); // a new tab takes the colours too
    });
    apply(m_options);
}

void OptionsController::addToMenu(QMenu* menu) {
    QAction* options = menu->addAction(tr("&Options..."), this, &OptionsController::showDialog);
    options->setObjectName(QStringLiteral("optionsAction"));
    menu->addSeparator();
    menu->addActions({m_wakeUp, m_cableDisconnect, m_reconnect});
}

OptionsDialog* OptionsController::showDialog() {
    auto* dialog = new OptionsDialog(&m_window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this, [this, dialog] {
        const ConnectionChoice before = m_window.connection().choice();
        apply(dialog->options());
        // chosen: a changed port or rate takes effect at once, as Motion Link's COMMUNICATIONS did.
        if (dialog->choice() != before) m_window.connectDrive(dialog->choice());
    });
    dialog->open();
    return dialog;
}

void OptionsController::apply(const AppOptions& options) {
    m_options = options;
    Theme::applyToTerminal(*m_window.terminal(), options.theme);
    if (editor::ProgramEditor* editor = m_window.editor()) Theme::applyToEditor(*editor, options.theme);
    m_highlighter.setColour(Theme::stepHighlight(options.theme));
    updateActions();
    emit optionsChanged(options);
}

void OptionsController::onConnected(bool connected) {
    updateActions();
    if (!connected) return;
    m_options = AppOptions::current();
    DriveConnection& connection = m_window.connection();
    // The autobaud sequence first (a multidrop drive never autobauds), then the wake-up of the axis.
    if (m_options.autobaud) connection.sendRaw(QByteArray(AppOptions::kAutobaudReturns, '\r'));
    wakeUpAxis();
}

void OptionsController::wakeUpAxis() {
    // chosen: only when an axis is chosen; on a single drive "\A" would be typed as text.
    if (m_options.axis.isNull()) return;
    m_window.connection().sendRaw("\\" + QByteArray(1, char(m_options.axis.toLatin1())));
}

void OptionsController::cableDisconnect() {
    DriveConnection& connection = m_window.connection();
    if (!connection.isConnected()) return;
    connection.session()->cancelPending(); // nothing new goes out
    m_disconnecting = true;
    m_window.terminal()->displayNotice(tr("Cable disconnect: finishing the command in flight..."));
    closeWhenQuiet();
}

void OptionsController::closeWhenQuiet() {
    DriveConnection& connection = m_window.connection();
    if (!m_disconnecting) return;
    if (connection.session() && connection.session()->state() == serialport::Bds5Session::State::Busy) return;
    m_disconnecting = false;
    connection.disconnectDrive();
    const bool simulated = connection.choice().kind == ConnectionChoice::Kind::Simulator;
    m_window.terminal()->displayNotice(
        simulated ? tr("The port is closed. Options > Reconnect powers the simulated drive up afresh.")
                  : tr("The port is closed: the cable may be unplugged. Options > Reconnect when it is back."));
}

void OptionsController::reconnect() {
    m_window.connectDrive(m_window.connection().choice());
}

void OptionsController::updateActions() {
    const bool connected = m_window.connection().isConnected();
    m_cableDisconnect->setEnabled(connected);
    m_reconnect->setEnabled(!connected && m_window.connection().hasLink());
    m_wakeUp->setEnabled(connected && !m_options.axis.isNull());
    m_wakeUp->setText(m_options.axis.isNull() ? tr("&Wake Up Axis") : tr("&Wake Up Axis %1").arg(m_options.axis));
}

} // namespace app
