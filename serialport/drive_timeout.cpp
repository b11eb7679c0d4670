// DriveTimeout: time-outs in the drive's time.
#include "drive_timeout.h"

#include "link.h"

#include <algorithm>
#include <cmath>

namespace serialport {

DriveTimeout::DriveTimeout(const Link& link, QObject* parent) : QObject(parent), m_link(link) {
    m_timer.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, &DriveTimeout::onWallTimeout);
}

// SERVODESK_TIMEOUT_SCALE=N multiplies every time-out on a port without a drive clock: for a drive behind a
// slow serial device server, and for tests that reach a simulator process through a pty on a loaded machine
// (the process may not run for seconds; tests/app/cli_test.py). 1 when unset or not a number >= 1.
int DriveTimeout::scaled(int ms) {
    static const double scale = [] {
        bool ok = false;
        const double s = qEnvironmentVariable("SERVODESK_TIMEOUT_SCALE").toDouble(&ok);
        return ok && s >= 1 ? s : 1.0;
    }();
    return int(std::min(double(ms) * scale, 3'600'000.0));
}

void DriveTimeout::start(int ms) {
    ++m_generation;
    m_active = true;
    if (!m_link.driveClockMs()) ms = scaled(ms);
    m_ms = ms;
    m_startDriveMs = m_link.driveClockMs().value_or(0);
    m_wall.start();
    m_timer.start(ms);
}

void DriveTimeout::stop() {
    ++m_generation;
    m_active = false;
    m_timer.stop();
}

void DriveTimeout::onWallTimeout() {
    const auto now = m_link.driveClockMs();
    if (!now) return expire(m_generation);
    if (m_link.isOpen() && m_wall.elapsed() < kMaxWallMs) {
        const double ran = *now - m_startDriveMs;
        if (ran < m_ms) return m_timer.start(std::max(5, int(std::ceil(m_ms - ran))));
    }
    // What the drive sent before its clock read this far is already posted to this thread: a queued call
    // runs after it, so an answer that came with the clock stops the time-out instead of losing the race.
    QMetaObject::invokeMethod(this, [this, g = m_generation] { expire(g); }, Qt::QueuedConnection);
}

void DriveTimeout::expire(quint64 generation) {
    if (generation != m_generation || !m_active) return;
    m_active = false;
    emit timeout();
}

} // namespace serialport
