// Sc750Debugger: the Compile menu's work (seed-sc750 §2.9). Compiles the current editor's ServoBASIC (the
// first error marks its line and column, L2632-L2646), downloads the .BIN with a progress dialog, runs,
// stops, continues and resets the program, keeps up to 10 breakpoints as editor-margin markers and sends
// them to the controller, and marks the line where the program stopped. Asynchronous; GUI thread only.
#pragma once

#include "sc750_editor_marks.h"

#include "drive_core/sc750/sc750_compiler.h"

#include <QObject>
#include <QPointer>
#include <QString>


namespace editor {
class ProgramEditor;
}

namespace app {

class Sc750Workspace;
class TransferDialog;

class Sc750Debugger final : public QObject {
    Q_OBJECT
public:
    enum class State { NoProgram, Downloading, Loaded, Running, Stopped, AtBreakpoint, Ended, Faulted };

    // The editor's marks (sc750_editor_marks.h).
    static constexpr int kCurrentLineMarker = kSc750CurrentLineMarker;
    static constexpr int kArrowMarker = kSc750ArrowMarker;
    static constexpr int kBreakpointMarker = kSc750BreakpointMarker;
    static constexpr int kErrorMarker = kSc750ErrorMarker;
    static constexpr int kMarkerMargin = kSc750MarkerMargin;
    static constexpr int kMaxBreakpoints = 10; // L2706

    explicit Sc750Debugger(Sc750Workspace& workspace);

    // Compile Program: true when the editor's text compiled; on an error the editor shows it.
    bool compile();
    // Run Program (Ctrl R): compiles when never compiled or changed since, downloads, runs.
    void run();
    // Options > Download BIN File: an image compiled earlier, downloaded and run without its source.
    void downloadBin(std::vector<std::uint8_t> bin);
    void stop();
    void continueProgram();
    void reset();
    // Set Breakpoint (F9) on the cursor's line of the current editor: sets or clears it.
    void toggleBreakpoint();
    void toggleBreakpointAt(editor::ProgramEditor& editor, int line); // 0-based line
    void clearBreakpoints();
    // 1-based lines that carry a breakpoint marker in the program's editor.
    QList<int> breakpointLines() const;

    State state() const { return m_state; }
    bool running() const { return m_state == State::Running || m_state == State::Downloading; }
    QString stateText() const;
    // The 0-based editor line marked as current (stopped, breakpoint), or -1.
    int currentLine() const { return m_currentLine; }
    // The last compile's error text ("LINE 3 COL 7 NEAR 'x': ..."), empty when it compiled.
    QString lastError() const { return m_lastError; }
    const drive_core::sc750::CompileResult& lastCompile() const { return m_compiled; }
    // The editor whose program was last run on the drive (its lines are the drive's), or nullptr.
    editor::ProgramEditor* programEditor() const;

    // The drive's own state from a status answer ("R,12,0,1,1"): on connecting, a program may be running
    // already (AUTOSTART, L2814-L2829) and only Stop regains control; one stopped shows its line again.
    void adoptDriveStatus(const QString& payload);
    // The session was created or dropped: wire its events. The current-line marks go with the old session
    // (another family's workspace may show the same editor next); the drive's status puts them back.
    void attachSession();
    // Prepares an editor's margin for breakpoints and the current-line marks (once per editor).
    void prepareEditor(editor::ProgramEditor& editor);

signals:
    void stateChanged();
    void message(const QString& text);
    void runStarted(); // the program was downloaded and R answered: the output window opens
    // The program stopped where its values can be read as they stand: a breakpoint, Stop or STOP, END, a
    // run-time error. The Variables window reads its watched names again.
    void halted();
    // Compile Program found an error (1-based line and column), for the error log.
    void compileFailed(int line, int column, const QString& message);

private:
    void setState(State state);
    void download(const std::vector<std::uint8_t>& bin);
    void startProgram();
    void sendBreakpoints();
    void markLine(int line); // 1-based drive line; 0 clears

    Sc750Workspace& m_workspace;
    QPointer<editor::ProgramEditor> m_program; // the editor whose program is on the drive
    QPointer<TransferDialog> m_progress;
    drive_core::sc750::CompileResult m_compiled;
    QString m_compiledText; // the text m_compiled came from
    QString m_lastError;
    State m_state = State::NoProgram;
    int m_currentLine = -1;
};

} // namespace app
