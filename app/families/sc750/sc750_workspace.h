// Sc750Workspace: Motion Dialogue inside ServoDesk (seed-sc750 §2.3). Owns the SC750 link and session
// while connected, the Compile and Controller menus, the Output window and Variables docks, and the
// ServoBASIC editing support of every .bas tab. Shown by the main window while the SC750 is the chosen
// family. GUI thread only.
#pragma once

#include "session_workspace.h"

#include "serialport/sc750_session.h"

#include <QHash>
#include <QPointer>

#include <functional>

#include <memory>

class QAction;
class QLabel;

namespace editor {
class ProgramEditor;
}

namespace app {

class MainWindow;
class Sc750Debugger;
class Sc750ErrorSource;
class Sc750OutputDock;
class Sc750StatusDisplay;
class Sc750VariablesDock;
class WatchView;

class Sc750Workspace final : public SessionWorkspace {
    Q_OBJECT
public:
    explicit Sc750Workspace(MainWindow& window);
    ~Sc750Workspace() override;

    QList<QMenu*> menus() const override;
    QList<QDockWidget*> docks() const override;
    QList<QAction*> toolBarActions() const override; // Compile, Run, Stop, Continue | Set Breakpoint
    QString statusText() const override;
    ErrorSource* errorSource() const override;
    QString sampleProgram() const override; // hello.bas
    QString busyReason() const override;

    // The session while the link is open, else nullptr.
    serialport::Sc750Session* session() const { return isConnected() ? m_session : nullptr; }
    Sc750Debugger& debugger() const { return *m_debugger; }
    Sc750OutputDock* outputDock() const { return m_output; }
    Sc750VariablesDock* variablesDock() const { return m_variables; }
    // The front-panel status display in the status bar (shown while the SC750 is the chosen family).
    Sc750StatusDisplay* statusDisplay() const { return m_display; }
    // Options > Axis Selection: 255 = RS-232 (default, L450), 0-254 multidrop.
    int axis() const { return m_axis; }
    void setAxis(int axis);
    // Sends one command frame; exactly one of done and failed runs (failed with the drive's "!nn TEXT" or a
    // time-out; when absent the reason goes to message()). False, and nothing runs, when not connected.
    using Done = std::function<void(const serialport::Sc750Reply&)>;
    using Failed = std::function<void(const QString&)>;
    bool send(char letter, const QString& payload, Done done, Failed failed = {});
    // Every action by its menu text without '&' and "...", for tests: "Compile Program", "Run Program".
    QAction* action(const QString& text) const;

    // Opens the Real Time Function Call dialog (non-modal) and returns it (the tour grabs it).
    QWidget* showFunctionCall();

private:
    void createMenus();
    void createOptionsMenu();
    void sessionCreated(serialport::DriveSession& session) override;
    void sessionOpened() override;
    void sessionEnding() override;
    void updateActions() override;
    void followEditor(editor::ProgramEditor* editor);
    void showCursorStatus();
    bool eventFilter(QObject* watched, QEvent* event) override;

    serialport::Sc750Session* m_session = nullptr; // the family's own session inside the DriveSession
    Sc750Debugger* m_debugger;
    Sc750OutputDock* m_output;
    Sc750VariablesDock* m_variables;
    Sc750ErrorSource* m_errors = nullptr;
    QMenu* m_compileMenu = nullptr;
    QMenu* m_optionsMenu = nullptr;
    QLabel* m_cursorLabel = nullptr; // "Axis 255  Line 0001 Col 01"
    Sc750StatusDisplay* m_display = nullptr;
    QPointer<editor::ProgramEditor> m_editor;
    QHash<quint64, std::pair<Done, Failed>> m_waiting;
    int m_axis = 255;
    bool m_axisFromLine = false; // m_axis is the line's axis (Machine > Use Axis), not the user's choice
    bool m_shown = false;
    bool m_placed = false; // the output dock moved under the editor on first show
};

} // namespace app
