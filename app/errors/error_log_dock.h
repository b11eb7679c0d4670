// ErrorLogDock: the drive's error log — ERR HIST read on demand (and on connecting), errors the drive
// reports as they arrive, severity icon and colour, the manual's fix hint, "go to line" for errors that
// cite a program line, ERR CLR and CSV export. GUI thread; talks only through the session.
#pragma once

#include "error_stream_scanner.h"

#include "serialport/bds5_session.h"

#include <QDockWidget>
#include <QPointer>

class QLabel;
class QTableView;

namespace app {

class DriveConnection;
class ErrorLogModel;

class ErrorLogDock final : public QDockWidget {
    Q_OBJECT
public:
    explicit ErrorLogDock(DriveConnection& connection, QWidget* parent = nullptr);

    ErrorLogModel& model() const { return *m_model; }
    QTableView* view() const { return m_view; }
    QString statusText() const;

    void readHistory();  // ERR HIST
    void clearHistory(); // ERR CLR, then ERR HIST to show it is empty
    // Writes the log as CSV; false (with the reason in the status line) if the file cannot be written.
    bool exportTo(const QString& path);
    void exportWithDialog();

signals:
    // The user asked to see drive program line n (1-based, as the drive counts it).
    void goToProgramLine(int driveLine);

private:
    void follow();
    void onFinished(quint64 id, const serialport::Bds5Response& response);
    void onBytes(const QByteArray& bytes);
    void activate(const QModelIndex& index);
    void setStatus(const QString& text);

    DriveConnection& m_connection;
    ErrorLogModel* m_model;
    QTableView* m_view;
    QLabel* m_status;
    ErrorStreamScanner m_scanner;
    QPointer<serialport::Bds5Session> m_session;
    quint64 m_historyId = 0;
};

} // namespace app
