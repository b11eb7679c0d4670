// Sc750ErrorSource: run-time errors, compile errors and FAULTCODE of the SC750 as error log rows.
#include "sc750_error_source.h"

#include "errors/program_line_jump.h"
#include "sc750_error_text.h"

#include "editor_area.h"
#include "editor_tabs.h"
#include "families/sc750/sc750_debugger.h"
#include "families/sc750/sc750_workspace.h"
#include "main_window.h"

#include "editor/program_editor.h"

namespace app {

Sc750ErrorSource::Sc750ErrorSource(Sc750Workspace& workspace)
    : ErrorSource(drive_core::DriveFamily::Sc750,
                  {tr("Read Fault"),
                   tr("Reads FAULTCODE, the fault the controller's display shows (the SC750 keeps no error history)"),
                   tr("Empties this log; Reset Program clears a run-time error (F 4) on the controller")},
                  &workspace),
      m_workspace(workspace) {
    connect(&workspace, &FamilyWorkspace::statusChanged, this, &Sc750ErrorSource::follow);
    connect(&workspace.debugger(), &Sc750Debugger::compileFailed, this,
            [this](int line, int column, const QString& message) {
                m_compiled = m_workspace.window().editor();
                model().addReported(Sc750ErrorText::compileError(line, column, message), QDateTime::currentDateTime());
            });
}

void Sc750ErrorSource::follow() {
    serialport::Sc750Session* session = m_workspace.session();
    if (session == m_session) return;
    m_session = session;
    if (!session) return;
    connect(session, &serialport::Sc750Session::runTimeError, this, [this](int code, int line, const QString& text) {
        model().addReported(Sc750ErrorText::runTimeError(code, line, text), QDateTime::currentDateTime());
        setStatus(tr("Run-time error at line %1: double-click the row to go there.").arg(line));
    });
    read(); // a fault present on connecting shows at once
}

void Sc750ErrorSource::read() {
    QPointer<Sc750ErrorSource> self(this);
    const bool sent = m_workspace.send(
        '?', {},
        [self](const serialport::Sc750Reply& reply) {
            if (self) self->onStatus(reply.payload);
        },
        [self](const QString& why) {
            if (self) self->setStatus(tr("The fault code was not read: %1").arg(why));
        });
    if (sent) setStatus(tr("Reading the fault code (FAULTCODE)..."));
}

void Sc750ErrorSource::onStatus(const QString& payload) {
    // "<state>,<line>,<faultcode>,<dp>,<configured>" (PROTOCOL.md §4); state F = stopped by a run-time error.
    const QStringList parts = payload.split(QLatin1Char(','));
    bool ok = false;
    const int code = parts.value(2).toInt(&ok);
    if (!ok) return setStatus(tr("The controller's status could not be read: \"%1\"").arg(payload));
    const ErrorLogModel::Entry now = Sc750ErrorText::fault(code);
    if (Sc750ErrorText::isNoFault(code)) {
        model().setHistory({});
        return setStatus(tr("FAULTCODE %1: %2.").arg(code).arg(now.message));
    }
    ErrorLogModel::Entry row = now;
    row.where = tr("FAULTCODE");
    if (code == 244 && parts.value(0) == QLatin1String("F")) row.programLine = parts.value(1).toInt();
    model().setHistory({row});
    setStatus(tr("FAULTCODE %1 (display %2): %3.").arg(code).arg(row.codeText, row.message));
}

void Sc750ErrorSource::clear() {
    model().clear();
    setStatus(tr("The log is empty; the controller's fault, if any, stays until it is reset."));
}

bool Sc750ErrorSource::showLine(const ErrorLogModel::Entry& entry) {
    // A compile error belongs to the editor compiled; a run-time error to the program on the drive.
    editor::ProgramEditor* editor = entry.code == 0 ? m_compiled.data() : m_workspace.debugger().programEditor();
    if (!editor) editor = m_workspace.window().editor();
    if (!editor) return true;
    m_workspace.window().editorArea()->tabs()->setCurrentWidget(editor);
    ProgramLineJump::showEditorLine(*editor, entry.programLine);
    return true;
}

} // namespace app
