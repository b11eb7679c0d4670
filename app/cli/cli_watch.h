// CliWatch: servodesk-cli's watch — the named values read through a serialport::WatchPoller (every family)
// every `every` ms for `for` seconds, one poll on the link at a time (a slow answer delays the next poll, it
// never queues a second), each sample stamped with the time it was taken: halfway between the poll and its
// answer, in seconds since the first poll, as the IDE's Watch Variables stamps them. The result is the
// scope's .CSV layout (scope/capture_csv.h) without its RECORD line, since the samples come when the link
// answers, not at RECORD's fixed interval (the scope takes its interval from the first two rows):
//   Time (s),POSITION (counts),VELOCITY (RPM)
//   0.011,0,0
// GUI thread; the session must outlive it.
#pragma once

#include "serialport/watch_choices.h"
#include "serialport/watch_poller.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

namespace app::cli {

struct CliWatchResult {
    enum class Status { Done, Refused, NoAnswer };
    Status status = Status::NoAnswer;
    QString csv; // Done: the file
    int samples = 0;
    int missed = 0; // polls that got no answer in time (skipped)
    QString reason; // Refused: the drive's words; NoAnswer: the last time-out
};

class CliWatch final : public QObject {
    Q_OBJECT
public:
    // choices: the family's watch choices for the names, in order (1 to 4).
    CliWatch(serialport::DriveSession& session, QList<serialport::WatchChoice> choices, int everyMs, double forSeconds,
             QObject* parent = nullptr);

    void start();

signals:
    void sampled(int samples);
    void finished(const app::cli::CliWatchResult& result);

private:
    void pollWhenDue();
    void onAnswered(const QList<double>& values);
    void onFailed(const QString& reason, bool refused);
    void finish(CliWatchResult::Status status, const QString& reason = {});
    double now_ms() const { return double(m_clock.nsecsElapsed()) / 1e6; }

    serialport::WatchPoller m_poller;
    QList<serialport::WatchChoice> m_choices;
    QStringList m_names;
    int m_everyMs = 0;
    double m_forMs = 0;
    QElapsedTimer m_clock;
    QTimer m_due; // the next poll
    double m_sentAt_ms = 0;
    double m_nextAt_ms = 0;
    CliWatchResult m_result;
    QString m_rows;
    bool m_done = false;
};

} // namespace app::cli
