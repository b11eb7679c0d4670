// Pmc960Workspace: the ORMEC PMC-960 inside ServoDesk (issue 9). Owns the PMC-960 link and its
// Pmc960Session while connected, the MPL menu (download and upload of the program buffer, Run Routine, Stop), the
// status panel and the parameter table. Shown by the main window while the PMC-960 is the chosen family;
// MPL editing itself (.mpl tabs) is MplLanguage's. GUI thread only.
#pragma once

#include "session_workspace.h"

#include "serialport/pmc960_session.h"

class QAction;

namespace app {

class MainWindow;
class Pmc960ErrorSource;
class VariableBrowser;
class Pmc960ProgramTransfer;
class Pmc960RoutineRunner;
class Pmc960RunDialog;
class Pmc960StatusDock;
class WatchView;

class Pmc960Workspace final : public SessionWorkspace {
    Q_OBJECT
public:
    explicit Pmc960Workspace(MainWindow& window);
    ~Pmc960Workspace() override;

    QList<QMenu*> menus() const override;
    QList<QDockWidget*> docks() const override;
    QList<QAction*> toolBarActions() const override; // Download, Run Routine, Stop
    QString statusText() const override;
    ErrorSource* errorSource() const override;
    QString sampleProgram() const override; // hello.mpl
    QString busyReason() const override;
    // MPL is typed at the controller's } prompt: the Terminal talks to it (Esc = Stop).
    bool typeIntoTerminal(const QByteArray& bytes, bool urgent) override;

    // The session while the link is open, else nullptr.
    serialport::Pmc960Session* session() const { return isConnected() ? m_session : nullptr; }
    Pmc960ProgramTransfer& transfer() const { return *m_transfer; }
    Pmc960RoutineRunner& runner() const { return *m_runner; }
    Pmc960StatusDock* statusDock() const { return m_status; }
    QDockWidget* parameterDock() const { return m_parameters; }
    VariableBrowser* parameterBrowser() const { return m_parameterBrowser; }
    QMenu* menu() const { return m_menu; }
    // Every MPL menu action by its text without '&' and "...": "Download Program", "Stop".
    QAction* action(const QString& text) const;

    // Stop: ESC to the controller at once (ahead of anything queued), which aborts a running program, a
    // wait or a half-typed command (digest §4.6); queued commands are dropped.
    void stop();
    // Run Routine: the labels of the editor's program to choose from; the choice is typed as B<label> (SM2
    // first if asked). Returns the dialog (open, not blocking), nullptr while disconnected.
    Pmc960RunDialog* runRoutine();

signals:
    // A transfer started or ended: docks leave the line alone while the program buffer is written.
    void busyChanged(bool busy);

private:
    void sessionCreated(serialport::DriveSession& session) override;
    void sessionOpened() override;
    void sessionClosed() override;
    void sessionEnding() override;
    void updateActions() override;

    serialport::Pmc960Session* m_session = nullptr; // the family's own session inside the DriveSession
    Pmc960ProgramTransfer* m_transfer;
    Pmc960StatusDock* m_status;
    QDockWidget* m_parameters;
    VariableBrowser* m_parameterBrowser;
    QMenu* m_menu;
    Pmc960ErrorSource* m_errors;
    Pmc960RoutineRunner* m_runner;
};

} // namespace app
