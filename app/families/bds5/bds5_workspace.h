// Bds5Workspace: the Kollmorgen BDS5 in the IDE, a family workspace as the SC750's and the PMC-960's are —
// its link and session (DriveConnection), its menus (Program, Variables, Scope, Tools, Capture), its entries
// in the Drive menu and its Drive and Debug toolbars (Run, Break, Stop, Monitor, Step...), its docks
// (Variables, Simulator I/O, DEP-01, Scope, Tuning, Capture), its error source, and the status bar's port,
// mode and state for it. The main window composes it like any other. GUI thread only.
//
//   auto* bds5 = new Bds5Workspace(window); // the connection exists from here on
//   bds5->build();                         // the tools, once the window's own parts exist
//   window.addWorkspace(bds5);
#pragma once

#include "drive/family_workspace.h"

#include "serialport/bds5_session.h"

class QToolBar;

namespace app {

class Bds5ErrorSource;
class CaptureDock;
class CaptureLog;
class Dep01Panel;
class DriveActions;
class DriveConnection;
class IoPanel;
class MainWindow;
class ProgramController;
class ScopeController;
class VariablesController;
class VariablesDock;

class Bds5Workspace final : public FamilyWorkspace {
    Q_OBJECT
public:
    explicit Bds5Workspace(MainWindow& window);
    // Makes the menus, toolbars and docks (they reach the window's editor area, terminal and options).
    void build();

    DriveConnection& connection() const { return *m_connection; }
    DriveActions& driveActions() const { return *m_driveActions; }
    ProgramController& programController() const { return *m_programController; }
    VariablesController& variablesController() const { return *m_variablesController; }
    ScopeController& scopeController() const { return *m_scopeController; }
    VariablesDock* variablesDock() const { return m_variablesDock; }
    IoPanel* ioPanel() const { return m_ioPanel; }
    Dep01Panel* dep01Panel() const { return m_dep01Panel; }
    CaptureLog& captureLog() const { return *m_captureLog; }
    CaptureDock* captureDock() const { return m_captureDock; }

    drive_core::DriveFamily family() const override { return drive_core::DriveFamily::Bds5; }
    QList<QMenu*> menus() const override { return m_menus; }
    QList<QDockWidget*> docks() const override;
    QList<QToolBar*> toolBars() const override { return m_toolBars; }
    QList<QAction*> driveMenuActions() const override;
    void activate(const ConnectionChoice& choice) override;
    void deactivate() override;
    bool isConnected() const override;
    QString statusText() const override;
    QString portText() const override;
    QString modeText() const override;
    LinkState linkState() const override;
    serialport::DriveSession* driveSession() const override;
    serialport::Link* link() const override;
    ErrorSource* errorSource() const override;
    QString busyReason() const override;
    QString sampleProgram() const override;
    QString referenceTopic() const override { return QStringLiteral("MA"); } // the command reference, A to Z
    bool typeIntoTerminal(const QByteArray& bytes, bool urgent) override;

private:
    MainWindow& m_window;
    DriveConnection* m_connection;
    Bds5ErrorSource* m_errors;
    QString m_mode; // from the drive's last prompt: "Interactive -->"
    DriveActions* m_driveActions = nullptr;
    ProgramController* m_programController = nullptr;
    VariablesController* m_variablesController = nullptr;
    ScopeController* m_scopeController = nullptr;
    VariablesDock* m_variablesDock = nullptr;
    IoPanel* m_ioPanel = nullptr;
    Dep01Panel* m_dep01Panel = nullptr;
    CaptureLog* m_captureLog = nullptr;
    CaptureDock* m_captureDock = nullptr;
    QList<QMenu*> m_menus;
    QList<QToolBar*> m_toolBars;
};

} // namespace app
