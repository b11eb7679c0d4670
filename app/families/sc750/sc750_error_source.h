// Sc750ErrorSource: the SC750's error log (issue 8) — run-time errors as the controller reports them (F 4
// with message and line), compile errors, and the fault the controller shows, read from its status
// (FAULTCODE, L1522-L1588) on connecting and by the dock's Read button ("Read Fault"). Activating a row
// that cites a line shows it in the .bas editor it came from. Talks only through the workspace's session.
//
// The dock's buttons for this family: the SC750 keeps no error history (no ERR HIST), so Read shows the
// current fault code as the log's one "history" row; Clear empties the log only — the controller's F 4 is
// cleared by Reset Program or the next Run, as in Motion Dialogue, never behind the user's back.
#pragma once

#include "errors/error_source.h"

#include "editor/program_editor.h"
#include "serialport/sc750_session.h"

#include <QPointer>

namespace app {

class Sc750Workspace;

class Sc750ErrorSource final : public ErrorSource {
    Q_OBJECT
public:
    explicit Sc750ErrorSource(Sc750Workspace& workspace);

    void read() override;
    void clear() override;
    bool showLine(const ErrorLogModel::Entry& entry) override;

private:
    void follow();
    void onStatus(const QString& payload);

    Sc750Workspace& m_workspace;
    QPointer<serialport::Sc750Session> m_session;
    QPointer<editor::ProgramEditor> m_compiled; // the editor of the last compile error
};

} // namespace app
