// DriveTimeout: a session's "no answer within N ms" timer, counted in the drive's own time where the link has
// a drive clock (a simulated drive). A loaded host can stall the simulator's thread for longer than a
// time-out (seconds beside a compiler or a CPU hog), and a drive that did not run for N ms was not silent
// for N ms: the time-out waits until the drive has run that long. On a real port, whose drive never stalls
// with the host, it is a plain single-shot wall-clock timer. A stalled clock (a simulator thread that no
// longer runs) still times out after kMaxWallMs. GUI thread only.
#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

namespace serialport {

class Link;

class DriveTimeout final : public QObject {
    Q_OBJECT
public:
    static constexpr int kMaxWallMs = 20000;

    explicit DriveTimeout(const Link& link, QObject* parent = nullptr);

    void start(int ms);
    // ms times SERVODESK_TIMEOUT_SCALE (a real port's time-outs only; see drive_timeout.cpp).
    static int scaled(int ms);
    void stop();
    bool isActive() const { return m_active; }

signals:
    void timeout();

private:
    void onWallTimeout();
    void expire(quint64 generation);

    const Link& m_link;
    QTimer m_timer;
    QElapsedTimer m_wall;
    int m_ms = 0;
    double m_startDriveMs = 0;
    bool m_active = false;
    quint64 m_generation = 0; // one per start() or stop(): a late expiry of an earlier one is dropped
};

} // namespace serialport
