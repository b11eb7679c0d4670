// MachineCompareDialog: Machine > Compare's result (issue 21), side by side — per axis, every variable and
// program line of its files (left) beside the drive's or a second backup's (right), the differing rows
// highlighted. Per row, "Take Drive's" writes the right value into the file, and "Take File's" sends the
// file's value to the drive (a program line: the file's whole program, downloaded and verified). Non-modal.
#pragma once

#include "machine/machine_job.h"

#include <QDialog>

class QCheckBox;
class QLabel;
class QListWidget;
class QPushButton;
class QTableWidget;

namespace app {

class MachineCompareDialog final : public QDialog {
    Q_OBJECT
public:
    // dir: the folder of project's files; rightTitle: "Drive" or the second backup's folder name. withDrive:
    // the right side is the drives (Take File's is offered).
    MachineCompareDialog(QList<machine::AxisReport> reports, machine::MachineProject project, QString dir,
                         QString rightTitle, bool withDrive, QWidget* parent = nullptr);

    QListWidget* axesList() const { return m_axes; }
    QTableWidget* table() const { return m_table; }
    QCheckBox* onlyDifferences() const { return m_onlyDifferences; }
    QPushButton* takeDrivesButton() const { return m_takeDrives; }
    QPushButton* takeFilesButton() const { return m_takeFiles; }
    QString statusText() const;
    // Selects axis id in the list (its rows fill the table).
    void showAxis(const QString& id);
    // The differing rows left, all axes.
    int differenceCount() const;

    // The dock's answer to sendToDrive / downloadToDrive: the rows sent now match, or why not.
    void drivesAnswer(const QString& id, bool ok, const QString& message);

signals:
    void sendToDrive(const QString& id, const QStringList& lines);
    void downloadToDrive(const QString& id, const QString& programText);

private:
    void fillAxes();
    void fillTable();
    void takeDrives();
    void takeFiles();
    QList<int> selectedRows() const; // indexes into the current axis's rows
    machine::AxisReport* current();
    void setStatus(const QString& text);

    QList<machine::AxisReport> m_reports;
    machine::MachineProject m_project;
    QString m_dir;
    bool m_withDrive;
    QListWidget* m_axes;
    QTableWidget* m_table;
    QCheckBox* m_onlyDifferences;
    QPushButton* m_takeDrives;
    QPushButton* m_takeFiles;
    QLabel* m_status;
    QList<int> m_shown;   // the current axis's row index of each table row
    QList<int> m_sending; // rows sent to the drive, marked matching when it answers
};

} // namespace app
