// AxisErrand: one small job on one axis of a line — a few command lines (a variable set to its file's value),
// or a program downloaded — for Compare's "take the file's" (issue 21). Selects the axis through an AxisLink,
// waits for its family's session, does the job, releases the axis. GUI thread; the line must outlive it.
#pragma once

#include "drive_core/drive.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <memory>

namespace serialport {
class AxisLink;
class DriveSession;
class DriveTimeout;
class Link;
struct LineAnswer;
struct TransferResult;
} // namespace serialport

namespace app::machine {

class AxisErrand final : public QObject {
    Q_OBJECT
public:
    AxisErrand(serialport::Link& line, drive_core::DriveFamily family, QString id, QObject* parent = nullptr);
    ~AxisErrand() override;

    void sendLines(const QStringList& lines); // each must be accepted
    // What the drive printed for each line sent, in order (its lines joined by a blank).
    const QStringList& answers() const { return m_answers; }
    void download(const QString& programText);

signals:
    void finished(bool ok, const QString& message); // once; message says what the drive holds when it failed

private:
    void begin();
    void onReady();
    void nextLine();
    void finish(bool ok, const QString& message);

    serialport::Link& m_line;
    drive_core::DriveFamily m_family;
    QString m_id;
    QStringList m_lines;
    QString m_current; // the line in flight
    QStringList m_answers;
    QString m_program;
    bool m_downloading = false;
    bool m_started = false;
    bool m_done = false;
    quint64 m_pending = 0;
    std::unique_ptr<serialport::AxisLink> m_axis;
    std::unique_ptr<serialport::DriveSession> m_session;
    std::unique_ptr<serialport::DriveTimeout> m_wait;
};

} // namespace app::machine
