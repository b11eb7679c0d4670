// ParameterLineTransfer: a parameter file read from or sent to the drive, for the families whose parameters are read and written one
// line at a time through DriveSession::sendLine — the SC750's .PRM (NAME reads a G frame, NAME=VALUE writes a
// P frame; serialport/sc750_parameter_file.h) and the PMC-960's parameter table as MPL lines (TGP? reads,
// TGP16 writes; serialport/pmc960_parameter_file.h). The BDS5's .VAR goes through its own transfers
// (variable_transfer.h picks). One line in flight at a time; a refusal is kept with its file line and the other lines
// still go, as the BDS5's send does; a line left unanswered goes once more. GUI thread; the session must
// outlive the transfer.
#pragma once

#include "serialport/drive_session.h"

#include <QList>
#include <QObject>
#include <QString>
#include <QStringList>

namespace app::machine {

struct VariableResult {
    enum class Status { Done, Refused, Lost };
    Status status = Status::Refused; // Refused: the drive refused a line (or the file had problems); Lost: no answer
    QString text;                    // dump: the file
    QList<serialport::TransferLineError> errors; // send: per file line (code 0: the file's problem, not sent)
    QString summary;                             // one line: what happened
};

class ParameterLineTransfer final : public QObject {
    Q_OBJECT
public:
    explicit ParameterLineTransfer(serialport::DriveSession& session, QObject* parent = nullptr);

    // false (and nothing starts) for a family without such a file here: the BDS5.
    static bool handles(drive_core::DriveFamily family);

    void dump();
    void send(const QString& fileText);

signals:
    void progress(int done, int total);
    void finished(const app::machine::VariableResult& result);

private:
    struct Step {
        int sourceLine = 0; // send: the file's line; dump: 0
        QString line;       // what goes to the drive
    };

    void next();
    void onAnswered(quint64 id, const serialport::LineAnswer& answer);
    void onLost(quint64 id, const QString& reason);
    void finishDump();
    void finishSend(const QString& stoppedBecause);
    void finish(VariableResult::Status status, const QString& summary);

    serialport::DriveSession& m_session;
    bool m_dumping = false;
    QList<Step> m_steps;
    QStringList m_answers; // dump: the value each read gave, in step order
    int m_at = 0;
    quint64 m_pending = 0;
    bool m_retried = false; // the line in flight went once unanswered already
    VariableResult m_result;
};

} // namespace app::machine
