// Sc750Debugger: compile, download with progress, run control, breakpoints and the current-line mark.
#include "sc750_debugger.h"

#include "sc750_editor_marks.h"
#include "sc750_workspace.h"

#include "main_window.h"
#include "transfer_dialog.h"

#include "editor/program_editor.h"
#include "serialport/sc750_download.h"

#include <QDir>
#include <QFileInfo>
#include <QSaveFile>

namespace app {

namespace {
// "07 NO STATEMENT ON LINE": the drive refused. A time-out is not a refusal: a program flooding the line
// with PRINT output can delay the answer past the session's time-out while the drive did set it.
bool isDriveRefusal(const QString& reason) {
    return reason.size() >= 2 && reason[0].isDigit() && reason[1].isDigit();
}

int markerCount(const editor::ProgramEditor& editor, int marker) {
    int n = 0;
    for (int line = editor.markerFindNext(0, 1 << marker); line >= 0;
         line = editor.markerFindNext(line + 1, 1 << marker))
        ++n;
    return n;
}
} // namespace

Sc750Debugger::Sc750Debugger(Sc750Workspace& workspace) : QObject(&workspace), m_workspace(workspace) {}

editor::ProgramEditor* Sc750Debugger::programEditor() const {
    return m_program;
}

QString Sc750Debugger::stateText() const {
    switch (m_state) {
    case State::NoProgram: return tr("No program");
    case State::Downloading: return tr("Downloading");
    case State::Loaded: return tr("Program loaded");
    case State::Running: return tr("Running");
    case State::Stopped: return tr("Stopped");
    case State::AtBreakpoint: return tr("At breakpoint");
    case State::Ended: return tr("Program ended");
    case State::Faulted: return tr("Run-time error (F 4)");
    }
    return {};
}

void Sc750Debugger::prepareEditor(editor::ProgramEditor& editor) {
    if (!defineSc750Marks(editor)) return; // prepared before
    connect(&editor, &QsciScintilla::marginClicked, this,
            [this, e = &editor](int margin, int line, Qt::KeyboardModifiers) {
                if (margin == kMarkerMargin) toggleBreakpointAt(*e, line);
            });
    // The error belongs to the text it was found in: the next edit takes it away.
    connect(&editor, &QsciScintilla::textChanged, this, [e = &editor] {
        if (e->markerFindNext(0, 1 << kErrorMarker) >= 0) clearCompileError(*e);
    });
}

bool Sc750Debugger::compile() {
    editor::ProgramEditor& editor = *m_workspace.window().editor();
    prepareEditor(editor);
    const QString text = editor.text();
    m_compiled = drive_core::sc750::compile(text.toStdString());
    m_compiledText = text;
    clearCompileError(editor);
    if (!m_compiled.ok()) {
        m_lastError = QString::fromStdString(m_compiled.error->text());
        showCompileError(editor, *m_compiled.error);
        emit message(tr("Compile error, line %1 col %2: %3")
                         .arg(m_compiled.error->line)
                         .arg(m_compiled.error->column)
                         .arg(QString::fromStdString(m_compiled.error->message)));
        emit compileFailed(m_compiled.error->line, m_compiled.error->column,
                           QString::fromStdString(m_compiled.error->message));
        return false;
    }
    m_lastError.clear();
    QString written;
    if (const QFileInfo source(editor.filePath()); !editor.filePath().isEmpty()) {
        // Success writes <basename>.BIN next to the program (L2646).
        QSaveFile bin(source.dir().filePath(source.completeBaseName() + QStringLiteral(".BIN")));
        if (bin.open(QIODevice::WriteOnly)) {
            bin.write(reinterpret_cast<const char*>(m_compiled.bin.data()), qint64(m_compiled.bin.size()));
            if (bin.commit()) written = tr(", written to %1").arg(QFileInfo(bin.fileName()).fileName());
        }
    }
    emit message(tr("Compiled: %1 bytes of code, %2 bytes of data%3")
                     .arg(m_compiled.program.codeBytes())
                     .arg(m_compiled.program.dataBytes())
                     .arg(written));
    return true;
}

void Sc750Debugger::run() {
    if (!m_workspace.session()) {
        emit message(tr("Not connected to an SC750: choose Drive > Connect..."));
        return;
    }
    if (m_state == State::Downloading) return;
    editor::ProgramEditor* editor = m_workspace.window().editor();
    // Compiles first when never compiled or modified since (L2668-L2686).
    if (m_compiledText != editor->text() || !m_compiled.ok()) {
        if (!compile()) return;
    }
    if (m_program && m_program != editor) m_program->markerDeleteAll(kCurrentLineMarker);
    m_program = editor;
    prepareEditor(*editor);
    // A running program refuses a download: stop it first (H is answered at any time).
    if (running() || m_state == State::Stopped || m_state == State::AtBreakpoint) m_workspace.send('H', {}, {});
    download(m_compiled.bin);
}

void Sc750Debugger::downloadBin(std::vector<std::uint8_t> bin) {
    if (!m_workspace.session()) {
        emit message(tr("Not connected to an SC750: choose Drive > Connect..."));
        return;
    }
    if (m_state == State::Downloading) return;
    if (running() || m_state == State::Stopped || m_state == State::AtBreakpoint) m_workspace.send('H', {}, {});
    if (m_program) m_program->markerDeleteAll(kCurrentLineMarker);
    m_program = nullptr; // no source: no lines to mark
    download(bin);
}

void Sc750Debugger::download(const std::vector<std::uint8_t>& bin) {
    serialport::Sc750Session* session = m_workspace.session();
    setState(State::Downloading);
    markLine(0);
    auto* transfer = new serialport::Sc750Download(*session, bin, session);
    const int total = int(bin.size());
    auto* progress = new TransferDialog(tr("Run Program"), tr("bytes"), [transfer] { transfer->cancel(); },
                                        &m_workspace.window());
    m_progress = progress;
    progress->setStage(tr("Downloading the program to the SC750..."));
    progress->showProgress(0, total);
    connect(session, &QObject::destroyed, progress, [progress] {
        progress->finish(TransferDialog::Outcome::Failed, tr("The connection to the SC750 closed."));
    });
    connect(transfer, &serialport::Sc750Download::progress, progress, &TransferDialog::showProgress);
    connect(transfer, &serialport::Sc750Download::finished, this, [this, transfer](bool ok, const QString& why) {
        transfer->deleteLater();
        if (m_progress)
            m_progress->finish(ok ? TransferDialog::Outcome::Done : TransferDialog::Outcome::Failed,
                               ok ? QString() : tr("Download failed: %1").arg(why));
        if (!ok) {
            setState(State::NoProgram);
            emit message(tr("Download failed: %1").arg(why));
            return;
        }
        setState(State::Loaded);
        if (m_program) sendBreakpoints();
        startProgram();
    });
    transfer->start();
}

void Sc750Debugger::startProgram() {
    m_workspace.send('R', {}, [this](const serialport::Sc750Reply&) {
        setState(State::Running);
        markLine(0);
        emit runStarted();
    });
}

void Sc750Debugger::stop() {
    if (auto* session = m_workspace.session()) session->sendStop(); // Ctrl C: program and motion (L1493)
}

void Sc750Debugger::continueProgram() {
    m_workspace.send('C', {}, [this](const serialport::Sc750Reply&) {
        setState(State::Running);
        markLine(0);
    });
}

void Sc750Debugger::reset() {
    m_workspace.send('X', {}, [this](const serialport::Sc750Reply&) {
        setState(m_state == State::NoProgram ? State::NoProgram : State::Loaded);
        markLine(0);
    });
}

void Sc750Debugger::adoptDriveStatus(const QString& payload) {
    // "S<state>,<line>,<faultcode>,<dp>,<configured>" (PROTOCOL.md): line is the current (next) line.
    const int line = payload.section(QLatin1Char(','), 1, 1).toInt();
    switch (payload.isEmpty() ? 'N' : payload.at(0).toLatin1()) {
    case 'L': setState(State::Loaded); break;
    case 'R': setState(State::Running); break;
    case 'S':
        setState(State::Stopped);
        markLine(line);
        break;
    case 'B':
        setState(State::AtBreakpoint);
        markLine(line);
        break;
    case 'E': setState(State::Ended); break;
    case 'F':
        setState(State::Faulted);
        markLine(line);
        break;
    default: setState(State::NoProgram); break;
    }
}

void Sc750Debugger::attachSession() {
    markLine(0); // stopped where the old session said: not known of this one until its status answers
    serialport::Sc750Session* session = m_workspace.session();
    if (session) session->disconnect(this); // the same session again after a reconnect: connected once
    if (!session) {
        setState(State::NoProgram);
        return;
    }
    connect(session, &serialport::Sc750Session::breakpointHit, this, [this](int line) {
        setState(State::AtBreakpoint);
        markLine(line);
        emit message(tr("Breakpoint at line %1").arg(line));
        emit halted();
    });
    connect(session, &serialport::Sc750Session::programStopped, this, [this](int line) {
        if (m_state == State::Downloading) return; // the H sent before a download
        setState(State::Stopped);
        markLine(line);
        emit halted();
    });
    connect(session, &serialport::Sc750Session::programEnded, this, [this](int) {
        setState(State::Ended);
        markLine(0);
        emit halted();
    });
    connect(session, &serialport::Sc750Session::runTimeError, this, [this](int code, int line, const QString& text) {
        setState(State::Faulted);
        markLine(line);
        emit message(tr("Run-time error %1 at line %2: %3").arg(code).arg(line).arg(text));
        emit halted();
    });
}

void Sc750Debugger::toggleBreakpoint() {
    editor::ProgramEditor& editor = *m_workspace.window().editor();
    int line = 0, index = 0;
    editor.getCursorPosition(&line, &index);
    toggleBreakpointAt(editor, line);
}

void Sc750Debugger::toggleBreakpointAt(editor::ProgramEditor& editor, int line) {
    prepareEditor(editor);
    const bool onDrive = m_program == &editor && m_state != State::NoProgram && m_state != State::Downloading;
    if (editor.markersAtLine(line) & (1 << kBreakpointMarker)) {
        editor.markerDelete(line, kBreakpointMarker);
        if (onDrive) m_workspace.send('B', QStringLiteral("-%1").arg(line + 1), {}, [](const QString&) {});
        return;
    }
    if (markerCount(editor, kBreakpointMarker) >= kMaxBreakpoints) {
        emit message(tr("At most %1 breakpoints can be set").arg(kMaxBreakpoints));
        return;
    }
    const int handle = editor.markerAdd(line, kBreakpointMarker);
    if (!onDrive) return;
    QPointer<editor::ProgramEditor> guard(&editor);
    m_workspace.send('B', QStringLiteral("+%1").arg(line + 1), {}, [this, guard, handle, line](const QString& why) {
        if (guard && isDriveRefusal(why)) guard->markerDeleteHandle(handle);
        emit message(tr("No breakpoint on line %1: %2").arg(line + 1).arg(why));
    });
}

void Sc750Debugger::clearBreakpoints() {
    if (editor::ProgramEditor* editor = m_workspace.window().editor()) editor->markerDeleteAll(kBreakpointMarker);
    if (m_program) m_program->markerDeleteAll(kBreakpointMarker);
    if (m_workspace.session()) m_workspace.send('B', QStringLiteral("*"), {});
}

QList<int> Sc750Debugger::breakpointLines() const {
    QList<int> lines;
    const editor::ProgramEditor* editor = m_program ? m_program.data() : m_workspace.window().editor();
    for (int line = editor->markerFindNext(0, 1 << kBreakpointMarker); line >= 0;
         line = editor->markerFindNext(line + 1, 1 << kBreakpointMarker))
        lines << line + 1;
    return lines;
}

void Sc750Debugger::sendBreakpoints() {
    m_workspace.send('B', QStringLiteral("*"), {});
    for (int line : breakpointLines()) {
        m_workspace.send('B', QStringLiteral("+%1").arg(line), {}, [this, line](const QString& why) {
            if (m_program && isDriveRefusal(why)) m_program->markerDelete(line - 1, kBreakpointMarker);
            emit message(tr("No breakpoint on line %1: %2").arg(line).arg(why));
        });
    }
}

void Sc750Debugger::markLine(int line) {
    editor::ProgramEditor* editor = m_program ? m_program.data() : nullptr;
    m_currentLine = -1;
    if (!editor) return;
    editor->markerDeleteAll(kCurrentLineMarker);
    editor->markerDeleteAll(kArrowMarker);
    if (line <= 0) return;
    m_currentLine = line - 1;
    editor->markerAdd(m_currentLine, kCurrentLineMarker);
    editor->markerAdd(m_currentLine, kArrowMarker);
    editor->ensureLineVisible(m_currentLine);
}

void Sc750Debugger::setState(State state) {
    if (m_state == state) return;
    m_state = state;
    emit stateChanged();
}

} // namespace app
