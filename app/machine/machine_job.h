// MachineJob: one pass over every axis of a machine on its shared line (issue 21) — Backup (read each axis's
// program and variables into a folder, with the project file naming them), Compare (read each axis and set it
// beside the folder's files, per variable and per program line) or Restore (send each axis its files, then
// read the variables back and compare). One axis at a time: selected through an AxisLink, served by its
// family's DriveSession, released before the next. A failed axis is reported with its reason and the job goes
// on to the next; an axis is never left without a report of what its drive holds. An empty program file (the
// drive held no program when backed up) is not sent: a download of nothing is refused by every family, and
// erasing a drive's program is its own editor's command; the report says the drive keeps its own, and
// Compare shows its lines as differences. GUI thread; the line must outlive the job.
#pragma once

#include "axis_compare.h"
#include "machine_project.h"
#include "parameter_line_transfer.h"

#include "serialport/drive_session.h"

#include <QList>
#include <QObject>
#include <QPointer>
#include <QString>
#include <QStringList>

#include <memory>

namespace serialport {
class AxisLink;
class DriveTimeout;
class Link;
} // namespace serialport

namespace app::machine {

class VariableTransfer;

struct AxisReport {
    enum class Outcome { Done, Differs, Failed, Cancelled };
    QString id;
    drive_core::DriveFamily family = drive_core::DriveFamily::Bds5;
    Outcome outcome = Outcome::Failed;
    QString message;        // one line: what happened on this axis, and why when it failed
    QString driveHolds;     // restore: what the drive holds now ("its old program", "the project's program ...")
    QStringList program;    // backup, compare: the program as the drive holds it
    QString variables;      // backup, compare, restore's check: the variable file as read from the drive
    QList<CompareRow> rows; // compare, restore's check: every variable and program line, the differing flagged
    bool ok() const { return outcome == Outcome::Done; }
};

class MachineJob final : public QObject {
    Q_OBJECT
public:
    enum class Kind { Backup, Compare, Restore };

    // dir: where Backup writes (created if need be) or Compare and Restore read the project's files.
    MachineJob(Kind kind, serialport::Link& line, MachineProject project, QString dir, QObject* parent = nullptr);
    ~MachineJob() override;

    void start();  // finished() follows once, never from inside start()
    void cancel(); // the axis in hand stops as soon as its drive allows; the others are not touched
    const QList<AxisReport>& reports() const { return m_reports; }
    const MachineProject& project() const { return m_project; }
    // The bytes this job moved on the line, both ways (for the line-rate figure).
    qint64 bytesSent() const { return m_sent; }
    qint64 bytesReceived() const { return m_received; }

signals:
    void stageChanged(const QString& stage); // "Axis B (2 of 4): reading the program"
    void progress(int done, int total);      // steps of the whole job
    void axisFinished(const app::machine::AxisReport& report);
    void finished(bool ok, const QString& summary);

private:
    enum class Step { Select, Program, Variables, Check, Next };
    void nextAxis();
    void beginAxis();
    void step(Step s);
    void onReady();
    void onTransfer(const serialport::TransferResult& result);
    void onVariables(const VariableResult& result);
    void endAxis(AxisReport::Outcome outcome, const QString& message);
    void finishJob();
    bool readFile(const QString& name, QString& text, QString& error) const;
    bool writeBackup(QString& error);
    void stage(const QString& what);
    void releaseAxis();

    Kind m_kind;
    serialport::Link& m_line;
    MachineProject m_project;
    QString m_dir;
    int m_at = -1;
    Step m_step = Step::Select;
    AxisReport m_report;
    QString m_fileProgram, m_fileVariables; // compare, restore: the axis's files
    std::unique_ptr<serialport::AxisLink> m_axisLink;
    std::unique_ptr<serialport::DriveSession> m_session;
    std::unique_ptr<VariableTransfer> m_variables;
    std::unique_ptr<serialport::DriveTimeout> m_wait;
    QList<AxisReport> m_reports;
    bool m_cancelled = false;
    bool m_finished = false;
    qint64 m_sent = 0, m_received = 0;
};

QString outcomeWord(AxisReport::Outcome outcome); // "done", "differs", "failed", "cancelled"

} // namespace app::machine
