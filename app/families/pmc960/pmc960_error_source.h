// Pmc960ErrorSource: the PMC-960's error log (issue 9) — every #xx the controller answers a command with
// (the IDE's own requests and what the user types in the Terminal) and the asynchronous #E0-#E3, decoded
// from the catalog; an error that stops a routine run with MPL > Run Routine names the command in the program
// and its line, as the runner placed it (issue 19; a double-click shows the line). The dock's Read button
// ("Read Last Error") reads the controller's error-status buffer (SE& G& V& SM& SB&, digest §4.5, L837-L839):
// the last error with where the axis was when it happened. Talks only through the workspace's session.
//
// The dock's buttons for this family: the controller keeps only its last error (no history list, nothing
// to clear), so Read fills the log's one "history" row from the `&` snapshot and Clear empties the log.
#pragma once

#include "errors/error_source.h"

#include "serialport/pmc960_session.h"

#include <QHash>
#include <QPointer>

namespace app {

class Pmc960Workspace;
struct Pmc960ProgramStop;

class Pmc960ErrorSource final : public ErrorSource {
    Q_OBJECT
public:
    explicit Pmc960ErrorSource(Pmc960Workspace& workspace);

    void read() override;
    void clear() override;
    bool showLine(const ErrorLogModel::Entry& entry) override;

    // A routine stopped on an error inside its program (Pmc960RoutineRunner::programFailed).
    void addProgramError(const Pmc960ProgramStop& stop);

private:
    void follow();
    void onFinished(quint64 id, const serialport::Pmc960Response& response);
    void onSnapshotPart(quint64 id, const QString& value);
    void showSnapshot();
    // The command typed at the prompt that the #xx answered, from what the terminal shows ("I4000+").
    QString typedCommand();

    Pmc960Workspace& m_workspace;
    QPointer<serialport::Pmc960Session> m_session;
    QHash<quint64, QString> m_asked;    // snapshot request id -> its command ("SE&")
    QHash<QString, QString> m_snapshot; // command -> the controller's answer
    QByteArray m_shown;                 // the terminal's bytes since the last prompt, up to kMaxShown
};

} // namespace app
