// MainWindow: composes the IDE — program editor in the centre, terminal dock, status bar, menus — and
// wires them to the DriveConnection. It does no protocol or file-format work itself. GUI thread only.
#pragma once

#include "connection_choice.h"

#include "serialport/bds5_session.h"

#include <QMainWindow>

class QLabel;

namespace editor {
class ProgramEditor;
}

namespace app {

class ConnectionDialog;
class DocumentController;
class DriveConnection;
class TerminalDock;
class TerminalWidget;

class MainWindow final : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Replaces the current connection (if any) with a new one and opens it.
    void connectDrive(const ConnectionChoice& choice);
    // Drive > Connect...: shows the dialog without blocking and returns it (the tour grabs it).
    ConnectionDialog* showConnectionDialog();
    // Puts back the window geometry and dock layout of the last session, if any.
    void restoreLayout();

    editor::ProgramEditor* editor() const { return m_editor; }
    TerminalDock* terminalDock() const { return m_terminalDock; }
    TerminalWidget* terminal() const;
    DriveConnection& connection() const { return *m_connection; }

protected:
    void closeEvent(QCloseEvent* event) override;
    void showEvent(QShowEvent* event) override;

private:
    void createMenus();
    void createStatusBar();
    void wireConnection();
    void updateTitle();
    void updateLinkStatus();
    void showMode(serialport::Bds5Mode mode, const QString& prompt);
    void showState();
    void showLinkError(const QString& message);
    void showAbout();

    editor::ProgramEditor* m_editor;
    TerminalDock* m_terminalDock;
    DriveConnection* m_connection;
    DocumentController* m_documents;
    QLabel* m_linkLabel = nullptr;
    QLabel* m_portLabel = nullptr;
    QLabel* m_modeLabel = nullptr;
    QLabel* m_stateLabel = nullptr;
    QAction* m_disconnectAction = nullptr;
    bool m_closeConfirmed = false;
    bool m_layoutRestored = false;
    bool m_shownOnce = false;
};

} // namespace app
