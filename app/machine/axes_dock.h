// AxesDock: View > Axes and the Machine menu (issue 21) — the multidrop line the machine's axes share (a
// simulated line of N axes, or a serial port or device server), a scan of it (each axis's ID, family and
// answer), and Use Axis, which points every tool of the IDE at the selected axis (the connection becomes that
// axis on the line; the status bar and title name it). After a scan each axis's status is read (enabled,
// fault, program checksum or model: axis_status.h). Back Up, Compare and Restore run a MachineJob over the
// line with a progress bar and a per-axis result in the table; Compare opens MachineCompareDialog. The line
// is held open across axis switches (a simulated line keeps its drives); a job or a scan first asks the IDE to
// leave the line (lineNeeded), as a real bus carries one conversation at a time.
#pragma once

#include "connection_choice.h"

#include "machine/axis_scan.h"
#include "machine/machine_compare_dialog.h"
#include "machine/machine_job.h"

#include <QDockWidget>
#include <QPointer>

#include <memory>
#include <optional>

class QAction;
class QComboBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace app {

class AxesDock final : public QDockWidget {
    Q_OBJECT
public:
    explicit AxesDock(QWidget* parent = nullptr);
    ~AxesDock() override;

    // The line, as the form above the table sets it. ids: a simulated line's axes ("A,B,C,D").
    void setSimulatedLine(drive_core::DriveFamily family, const QString& ids);
    void setPortLine(drive_core::DriveFamily family, const QString& port, int baud);
    // The IDE's family, which the line form takes until a line has been set up (a line in use stays).
    void followFamily(drive_core::DriveFamily family);
    // A simulated line's speed (simulated seconds per wall second; 1, real time, unless a test asks).
    void setSimulatorSpeed(double factor) { m_speed = factor; }

    // What the buttons and the Machine menu do, without their folder dialogs (tests, the tour).
    // A backup's project sets the line up as it names it (its family, its port, or a simulated line of its
    // axes) and lists its axes; Compare and Restore then start in its folder.
    void openProject(const QString& dir);
    void scan();
    void useAxis(const QString& id);
    void backUpTo(const QString& dir);
    void compareWith(const QString& dir);
    void restoreFrom(const QString& dir);
    // Two backups side by side, no drive: each axis of a beside the same axis of b ("Take Right" writes a's).
    void compareBackups(const QString& a, const QString& b);
    // Every axis executes line and none answers (the BDS5's '\*'); refused, in the status, for a family
    // whose line has no broadcast.
    void broadcast(const QString& line);
    void cancel();

    bool isBusy() const { return m_job || m_scan || m_errand; }
    QTableWidget* table() const { return m_table; }
    QString statusText() const;
    QProgressBar* progressBar() const { return m_progress; }
    MachineCompareDialog* compareDialog() const { return m_compare; }
    std::shared_ptr<serialport::Link> line() const { return m_line; }
    drive_core::DriveFamily family() const;
    // The Machine menu's actions.
    QList<QAction*> menuActions() const;

signals:
    void axisChosen(const app::ConnectionChoice& choice);
    void lineNeeded(const std::shared_ptr<serialport::Link>& line); // leave it: a scan or a job is about to run
    void busyChanged(bool busy);
    void scanFinished(int axes);
    void jobFinished(bool ok, const QString& summary);

private:
    QWidget* makeLineForm();
    bool ensureLine(); // the line the form describes, open; false (status says why) when it cannot be
    void showLineKind();
    void runJob(machine::MachineJob::Kind kind, machine::MachineProject project, const QString& dir);
    void showScan(const QList<machine::FoundAxis>& axes);
    void readStatus(int row, const QString& found);
    void showAxisResult(const machine::AxisReport& report);
    void setBusy(bool busy);
    bool saidBusy(); // true, with the status saying so, while a scan, a job or an errand runs
    void setStatus(const QString& text);
    machine::MachineProject scannedProject() const;
    // dir's project when it is of the line's family; nullopt, with the status saying why, when not.
    std::optional<machine::MachineProject> projectOfThisLine(const QString& dir);
    void chooseFolderAnd(void (AxesDock::*then)(const QString&), bool existing);
    void startErrand(const QString& id, const QStringList& lines, const QString* program);
    void chooseBackupsToCompare();

    QComboBox* m_familyBox;
    QComboBox* m_kindBox; // simulated line, or port
    QLineEdit* m_where;   // the simulated line's IDs, or the port
    QComboBox* m_baudBox;
    QLineEdit* m_callIds; // the IDs a scan calls
    QTableWidget* m_table;
    QProgressBar* m_progress;
    QLabel* m_status;
    QPushButton* m_cancel;
    QAction* m_scanAction;
    QAction* m_useAction;
    QAction* m_backUpAction;
    QAction* m_compareAction;
    QAction* m_compareBackupsAction;
    QAction* m_restoreAction;
    QAction* m_broadcastAction;
    QAction* m_openAction;
    QString m_projectDir; // the last backup written or project opened: where the folder dialogs start
    std::shared_ptr<serialport::Link> m_line;
    QString m_lineKey; // what m_line was made from: a new form makes a new line
    double m_speed = 1;
    std::unique_ptr<machine::AxisScan> m_scan;
    std::unique_ptr<machine::MachineJob> m_job;
    QPointer<QObject> m_errand;
    QPointer<MachineCompareDialog> m_compare;
};

} // namespace app
