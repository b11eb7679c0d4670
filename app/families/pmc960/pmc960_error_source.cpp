// Pmc960ErrorSource: #xx answers, asynchronous E-codes and the `&` error snapshot as error log rows.
#include "pmc960_error_source.h"

#include "errors/program_line_jump.h"
#include "pmc960_error_text.h"

#include "families/pmc960/pmc960_program_transfer.h"
#include "families/pmc960/pmc960_routine_runner.h"
#include "families/pmc960/pmc960_workspace.h"

#include "editor_area.h"
#include "editor_tabs.h"
#include "main_window.h"

#include "editor/program_editor.h"

#include <utility>

namespace app {

namespace {
// The error-status buffer's displays, the error code first (L839).
const char* const kSnapshot[] = {"SE&", "G&", "V&", "SM&", "SB&"};
constexpr int kMaxDetail = 40; // a download's chunk is more than a command: keep its start
constexpr int kMaxShown = 256;
} // namespace

Pmc960ErrorSource::Pmc960ErrorSource(Pmc960Workspace& workspace)
    : ErrorSource(
          drive_core::DriveFamily::Pmc960,
          {tr("Read Last Error"),
           tr("SE& and the error-status buffer: the controller's last error, with the position, speed, mode and "
              "label at the time"),
           tr("Empties this log (the PMC-960 keeps only its last error, which the next one replaces)")},
          &workspace),
      m_workspace(workspace) {
    connect(&workspace, &FamilyWorkspace::statusChanged, this, &Pmc960ErrorSource::follow);
}

void Pmc960ErrorSource::follow() {
    serialport::Pmc960Session* session = m_workspace.session();
    if (session == m_session) return;
    m_session = session;
    m_asked.clear();
    if (!session) return;
    connect(session, &serialport::Pmc960Session::finished, this, &Pmc960ErrorSource::onFinished);
    connect(session, &serialport::Pmc960Session::failed, this,
            [this](quint64 id, const QString&) { onSnapshotPart(id, {}); });
    // A #xx at the prompt: an E-code (ESTOP' in motion, FAULT', ...) or the answer to a typed command.
    // The session shows the bytes before it decodes their #xx, so the echoed command is here by then.
    connect(session, &serialport::Pmc960Session::shownReceived, this, [this](const QByteArray& bytes) {
        m_shown.append(bytes);
        if (m_shown.size() > kMaxShown) m_shown.remove(0, m_shown.size() - kMaxShown);
    });
    connect(session, &serialport::Pmc960Session::asyncError, this, [this](int code, const QString&) {
        const QString command = typedCommand();
        // The error that stopped a routine typed as B<label> is not B's: the runner places it in the program
        // (SB&) and its row comes from there (addProgramError).
        if (m_workspace.runner().isProgramError(code)) return;
        model().addReported(Pmc960ErrorText::entry(code, command), QDateTime::currentDateTime());
    });
}

void Pmc960ErrorSource::onFinished(quint64 id, const serialport::Pmc960Response& response) {
    if (m_asked.contains(id)) return onSnapshotPart(id, response.error ? QString() : response.value);
    if (response.error == 0) return;
    QString command = QString::fromLatin1(response.command).simplified();
    if (command.size() > kMaxDetail) command = command.left(kMaxDetail) + QStringLiteral("...");
    model().addReported(Pmc960ErrorText::entry(response.error, command), QDateTime::currentDateTime());
}

QString Pmc960ErrorSource::typedCommand() {
    // "<echo of the typed line> #B6 <cr><lf><id> }": the echo stands between the previous prompt and the
    // code. An E-code at an idle prompt has none (or names the command it interrupted, which is right too).
    const QByteArray shown = std::exchange(m_shown, {});
    const qsizetype hash = shown.lastIndexOf('#');
    if (hash < 0) return {};
    const QByteArray line = shown.left(hash);
    const QString command = QString::fromLatin1(line.mid(line.lastIndexOf('}') + 1)).simplified();
    return command.size() > kMaxDetail ? command.left(kMaxDetail) + QStringLiteral("...") : command;
}

void Pmc960ErrorSource::addProgramError(const Pmc960ProgramStop& stop) {
    ErrorLogModel::Entry row = Pmc960ErrorText::entry(stop.code, stop.detail);
    row.programLine = stop.editorLine;
    model().addReported(row, QDateTime::currentDateTime());
}

// A program error's line is the downloaded program's: its editor if still open, else the current one.
bool Pmc960ErrorSource::showLine(const ErrorLogModel::Entry& entry) {
    editor::ProgramEditor* editor = m_workspace.transfer().downloadedEditor();
    if (editor)
        m_workspace.window().editorArea()->tabs()->setCurrentWidget(editor);
    else
        editor = m_workspace.window().editor();
    if (editor) ProgramLineJump::showEditorLine(*editor, entry.programLine);
    return true;
}

void Pmc960ErrorSource::read() {
    if (!m_session) return setStatus(tr("Not connected: the last error was not read."));
    if (!m_asked.isEmpty()) return; // one read at a time
    m_snapshot.clear();
    for (const char* command : kSnapshot) m_asked.insert(m_session->send(command), QString::fromLatin1(command));
    setStatus(tr("Reading the last error (SE&)..."));
}

void Pmc960ErrorSource::onSnapshotPart(quint64 id, const QString& value) {
    const QString command = m_asked.take(id);
    if (command.isEmpty()) return;
    m_snapshot.insert(command, value);
    if (m_asked.isEmpty()) showSnapshot();
}

void Pmc960ErrorSource::showSnapshot() {
    bool ok = false;
    const int code = m_snapshot.value(QStringLiteral("SE&")).toInt(&ok, 16);
    if (!ok) return setStatus(tr("The controller did not give its last error."));
    if (code == 0) {
        model().setHistory({});
        return setStatus(tr("SE& = 00: no error since power-up."));
    }
    ErrorLogModel::Entry row = Pmc960ErrorText::entry(code);
    // SB& is "<label> <count>": the last @ label passed and the commands executed since (L1466-L1474).
    const QStringList label = m_snapshot.value(QStringLiteral("SB&")).split(QLatin1Char(' '), Qt::SkipEmptyParts);
    QStringList at;
    if (const QString g = m_snapshot.value(QStringLiteral("G&")); !g.isEmpty()) at << tr("position %1").arg(g);
    if (const QString v = m_snapshot.value(QStringLiteral("V&")); !v.isEmpty()) at << tr("speed %1").arg(v);
    if (const QString m = m_snapshot.value(QStringLiteral("SM&")); !m.isEmpty()) at << tr("mode %1").arg(m);
    if (label.size() == 2) at << tr("label %1 + %2").arg(label[0], label[1]);
    row.detail = at.join(QStringLiteral(", "));
    row.where = tr("last error (&)");
    model().setHistory({row});
    setStatus(tr("Last error %1: %2.").arg(row.codeText, row.message));
}

void Pmc960ErrorSource::clear() {
    model().clear();
    setStatus(tr("The log is empty."));
}

} // namespace app
