// FaultLink wraps any Link and damages what crosses it, with a seed: dropped, corrupted (one bit flipped)
// and duplicated bytes, delays and stalls, per direction, and a sudden close (the cable pulled). For the
// reliability tests; sessions above it must notice and recover or fail with a reason.
#pragma once

#include "link.h"

#include <QElapsedTimer>
#include <QTimer>

#include <deque>
#include <random>

namespace serialport {

class FaultLink final : public Link {
    Q_OBJECT
public:
    struct Faults {
        double drop = 0;      // probability a byte is lost
        double corrupt = 0;   // probability a byte has one bit flipped
        double duplicate = 0; // probability a byte arrives twice
        int delayMs = 0;      // every chunk arrives this much later (order kept)
        double stall = 0;     // probability a chunk is held back stallMs longer (order kept)
        int stallMs = 0;
    };

    // inner: the link to damage (owned by the caller, outlives this). toDrive / fromDrive: the faults of
    // each direction. seed: the same seed damages the same bytes.
    FaultLink(Link& inner, quint32 seed, Faults toDrive, Faults fromDrive, QObject* parent = nullptr);

    void open() override { m_inner.open(); }
    void close() override { m_inner.close(); }
    bool isOpen() const override { return m_inner.isOpen() && !m_cut; }
    void write(const QByteArray& bytes) override;
    QString description() const override { return tr("%1 (faulty)").arg(m_inner.description()); }
    int baudRate() const override { return m_inner.baudRate(); }
    int quietMs() const override { return m_inner.quietMs(); }
    std::optional<double> driveClockMs() const override { return m_inner.driveClockMs(); }

    // The cable is pulled: nothing passes any more, closed() and errorOccurred() follow.
    void cut();
    void setFaults(Faults toDrive, Faults fromDrive);

    struct Counters {
        qint64 bytes = 0, dropped = 0, corrupted = 0, duplicated = 0, stalled = 0;
    };
    const Counters& toDriveCounters() const { return m_counters[0]; }
    const Counters& fromDriveCounters() const { return m_counters[1]; }

private:
    enum Direction { ToDrive = 0, FromDrive = 1 };
    QByteArray damage(const QByteArray& bytes, Direction direction);
    void pass(QByteArray bytes, Direction direction);
    void deliverDue();

    struct Pending {
        qint64 dueMs;
        QByteArray bytes;
        Direction direction;
    };

    Link& m_inner;
    Faults m_faults[2];
    Counters m_counters[2];
    std::mt19937 m_random;
    std::deque<Pending> m_pending; // in order of arrival; due times never decrease per direction
    QTimer m_timer;
    QElapsedTimer m_clock;
    bool m_cut = false;
};

} // namespace serialport
