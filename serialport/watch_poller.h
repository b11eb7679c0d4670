// WatchPoller: reads a handful of a drive's values, one sample at a time, through its DriveSession — the
// family-neutral half of "watch" (servodesk-cli watch today). The BDS5 prints them with one "P A B" line at
// its prompt; the SC750 answers a G frame per variable, a program running or not; the PMC-960 answers its
// out-of-band status polls (<attn> g f v i for G!, SF!, V!, I!) at any time. The names are the family's
// watch choices (watch_choices.h). The IDE's Watch Variables reads through it for every family
// (app/scope/session_watch_source); its polls go by DriveSession::sendQuiet, so the BDS5's P stays out of the
// terminal.
// GUI thread; never blocks. The session must outlive the poller.
//
//   poller.poll({"POSITION", "VELOCITY"});   // later: answered({1024, 30.5}) or failed("...", refused)
#pragma once

#include "drive_session.h"

#include <QList>
#include <QObject>
#include <QStringList>

namespace serialport {

class WatchPoller final : public QObject {
    Q_OBJECT
public:
    explicit WatchPoller(DriveSession& session, QObject* parent = nullptr);

    // Reads one value for each name (watch choices of the session's family), in order: exactly one of
    // answered() or failed() follows, unless cancel() comes first.
    void poll(const QStringList& names);
    // Forgets the poll in flight: its answer, if any, is dropped.
    void cancel();
    bool isPolling() const { return m_pending != 0; }
    // The shortest time from one poll to the next that leaves the link room for the family's other polls.
    int minimumIntervalMs() const { return minimumIntervalMs(m_session.family()); }
    static int minimumIntervalMs(drive_core::DriveFamily family);

signals:
    // One value per name; an empty list when the answer held no usable sample (a damaged line): poll again.
    void answered(const QList<double>& values);
    // refused: the drive answered with an error (its words in reason), which polling again will not change;
    // otherwise no answer came in time (the link may recover).
    void failed(const QString& reason, bool refused);

private:
    void pollNext();
    void onAnswered(quint64 id, const LineAnswer& answer);
    void onStatusPolled(quint64 id, char letter, const QString& value);
    void onLost(quint64 id, const QString& reason);
    void take(const QString& word);

    DriveSession& m_session;
    QStringList m_names;
    QList<double> m_values; // read so far in this poll
    quint64 m_pending = 0;  // the request in flight, 0 when none
};

} // namespace serialport
