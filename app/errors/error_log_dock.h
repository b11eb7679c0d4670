// ErrorLogDock: the drive's error log for the family chosen in Drive > Connect — the drive's own record
// read on demand (BDS5 ERR HIST, SC750 FAULTCODE, PMC-960 `&` snapshot), errors the drive reports as they
// arrive, severity icon and colour, the manual's fix hint, "go to line" for errors that cite a program
// line, Clear and CSV export. Each family's rows come from its ErrorSource. GUI thread.
#pragma once

#include "drive_core/drive.h"

#include <QDockWidget>
#include <QList>

class QLabel;
class QPushButton;
class QTableView;

namespace app {

class ErrorLogModel;
class ErrorSource;

class ErrorLogDock final : public QDockWidget {
    Q_OBJECT
public:
    // Empty until a family's source is added: the first one added is shown until setFamily.
    explicit ErrorLogDock(QWidget* parent = nullptr);

    // A family's source (FamilyWorkspace::errorSource); the dock shows it while that family is chosen.
    void addSource(ErrorSource* source);
    void setFamily(drive_core::DriveFamily family);
    ErrorSource& source() const { return *m_current; }
    ErrorSource* source(drive_core::DriveFamily family) const;

    // The shown family's rows.
    ErrorLogModel& model() const;
    QTableView* view() const { return m_view; }
    QPushButton* readButton() const { return m_read; }
    QString statusText() const;

    void readHistory();  // the Read button: BDS5 ERR HIST, SC750 fault code, PMC-960 error snapshot
    void clearHistory(); // the Clear button: BDS5 ERR CLR then ERR HIST; the others empty the log
    // Writes the log as CSV; false (with the reason in the status line) if the file cannot be written.
    bool exportTo(const QString& path);
    void exportWithDialog();

signals:
    // The user asked to see BDS5 program line n (1-based, as the drive counts it); other families' sources
    // show their lines themselves.
    void goToProgramLine(int driveLine);

private:
    void showSource(ErrorSource* source);
    void activate(const QModelIndex& index);
    void setStatus(const QString& text);

    QList<ErrorSource*> m_sources;
    ErrorSource* m_current = nullptr;
    QTableView* m_view;
    QPushButton* m_read;
    QPushButton* m_clear;
    QLabel* m_status;
};

} // namespace app
