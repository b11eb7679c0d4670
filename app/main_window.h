// MainWindow: composes the IDE — program editor in the centre, terminal dock, status bar, menus — and
// wires them to the DriveConnection. It does no protocol or file-format work itself. GUI thread only.
#pragma once

#include "connection_choice.h"

#include "serialport/bds5_session.h"

#include <optional>

#include <QHash>
#include <QMainWindow>

class QLabel;
class QMenu;
class QToolBar;

namespace editor {
class DiagnosticsStatus;
class OutlineDock;
class ProgramEditor;
}

namespace app {

class AxesDock;
class Bds5Workspace;
class CaptureDock;
class CaptureLog;
class ConnectionDialog;
class DebugHighlighter;
class DocumentController;
class EditorArea;
class FamilyWorkspace;
class DriveActions;
class DriveConnection;
class HelpBrowser;
class OptionsController;
class ProgramController;
class VariablesController;
class ScopeController;
class VariablesDock;
class ErrorLogDock;
class IoPanel;
class Dep01Panel;
class TerminalDock;
class TerminalWidget;

class MainWindow final : public QMainWindow {
    Q_OBJECT
public:
    // family: the drive family the IDE starts with (servodesk --drive); the first tab is its sample program
    // (hello.bds, hello.bas, hello.mpl). Connecting is connectDrive()'s.
    explicit MainWindow(drive_core::DriveFamily family = drive_core::DriveFamily::Bds5, QWidget* parent = nullptr);
    ~MainWindow() override;

    // Replaces the current connection (if any) with a new one and opens it: the choice's family workspace
    // connects, and its menus, toolbars and docks replace the previous family's.
    void connectDrive(const ConnectionChoice& choice);
    // Drive > Connect...: shows the dialog without blocking and returns it (the tour grabs it).
    ConnectionDialog* showConnectionDialog();
    // Puts back the window geometry and dock layout of the last session, if any.
    void restoreLayout();

    // The current tab's editor (never null). Ask again each time: tabs come and go; follow
    // currentEditorChanged, or editorArea()->tabs() for every open editor.
    editor::ProgramEditor* editor() const;
    EditorArea* editorArea() const { return m_editorArea; }
    TerminalDock* terminalDock() const { return m_terminalDock; }
    TerminalWidget* terminal() const;
    // The BDS5's workspace and, through it, its connection and tools (app/families/bds5/bds5_workspace.h).
    Bds5Workspace& bds5() const { return *m_bds5; }
    DriveConnection& connection() const;
    DriveActions& driveActions() const;
    DebugHighlighter& debugHighlighter() const { return *m_debugHighlighter; }
    OptionsController& optionsController() const { return *m_optionsController; }
    // The BDS5 reference dock; helpBrowser()->showTopic("VMAX") opens it at a topic (the editor's F1).
    HelpBrowser* helpBrowser() const { return m_helpBrowser; }
    // The Outline dock (labels and tasks of the current program; Search > Go to Label).
    editor::OutlineDock* outlineDock() const { return m_outlineDock; }
    // The BDS5's Program menu (downloads, uploads, verify) and Drive-menu actions.
    ProgramController& programController() const;
    // The Scope menu, the Scope dock and the Tuning panel dock (issue 6).
    ScopeController& scopeController() const;
    // The Error Log (every family's errors: FamilyWorkspace::errorSource).
    ErrorLogDock* errorLogDock() const { return m_errorLogDock; }
    // Issue 21: the Axes panel and the Machine menu (a multidrop line's axes, backup, compare, restore).
    AxesDock* axesDock() const { return m_axesDock; }
    // The axis of a multidrop line every tool talks to, "" for a single drive.
    const QString& axisInUse() const { return m_axis; }
    // Issues 8 and 9: the SC750 and PMC-960 workspaces. The window takes ownership; menus and docks are
    // added hidden and shown while the workspace's family is the connected one.
    void addWorkspace(FamilyWorkspace* workspace);
    FamilyWorkspace* workspace(drive_core::DriveFamily family) const;
    drive_core::DriveFamily activeFamily() const { return m_family; }

signals:
    void currentEditorChanged(editor::ProgramEditor* editor);
    void familyChanged(drive_core::DriveFamily family);

protected:
    void closeEvent(QCloseEvent* event) override;
    void showEvent(QShowEvent* event) override;

private:
    void createMenus();
    void createDocks(); // options, help, outline, error log, axes (before createMenus)
    void createStatusBar();
    void resizeToFitScreen();
    void typeIntoTerminal(const QByteArray& bytes, bool urgent);
    void followEditor(editor::ProgramEditor* current); // outline, diagnostics count, F1 -> reference
    void updateTitle();
    void updateLinkStatus();
    void showLinkError(const QString& message);
    void showAbout();
    void showFamily(drive_core::DriveFamily family); // menus, toolbars and docks of that family only
    void openSampleProgram(drive_core::DriveFamily family); // as an unnamed tab, never written back
    void disconnectActive();

    EditorArea* m_editorArea;
    TerminalDock* m_terminalDock;
    Bds5Workspace* m_bds5;
    DocumentController* m_documents;
    DebugHighlighter* m_debugHighlighter = nullptr;
    OptionsController* m_optionsController = nullptr;
    HelpBrowser* m_helpBrowser = nullptr;
    editor::OutlineDock* m_outlineDock = nullptr;
    editor::DiagnosticsStatus* m_diagnosticsStatus = nullptr;
    ErrorLogDock* m_errorLogDock = nullptr;
    AxesDock* m_axesDock = nullptr;
    QString m_axis;                              // the axis in use on m_axisLine, "" for a single drive
    std::shared_ptr<serialport::Link> m_axisLine; // the Axes panel's line the connection is on, if any
    QLabel* m_linkLabel = nullptr;
    QLabel* m_portLabel = nullptr;
    QLabel* m_modeLabel = nullptr;
    QLabel* m_stateLabel = nullptr;
    QAction* m_disconnectAction = nullptr;
    QMenu* m_driveMenu = nullptr;
    QMenu* m_viewMenu = nullptr;
    QMultiHash<FamilyWorkspace*, QToolBar*> m_familyToolBars;  // a workspace's own, shown with its family
    QMultiHash<FamilyWorkspace*, QAction*> m_familyDriveItems; // its Drive-menu entries, likewise
    QList<FamilyWorkspace*> m_workspaces;
    drive_core::DriveFamily m_family = drive_core::DriveFamily::Bds5;
    std::optional<drive_core::DriveFamily> m_terminalHintShown; // "has no terminal" said for this family
    bool m_closeConfirmed = false;
    bool m_layoutRestored = false;
    bool m_shownOnce = false;
};

} // namespace app
