// FaultLink: seeded damage between a session and its link.
#include "fault_link.h"

#include <algorithm>

namespace serialport {

FaultLink::FaultLink(Link& inner, quint32 seed, Faults toDrive, Faults fromDrive, QObject* parent)
    : Link(parent), m_inner(inner), m_random(seed) {
    m_faults[ToDrive] = toDrive;
    m_faults[FromDrive] = fromDrive;
    m_clock.start();
    m_timer.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, &FaultLink::deliverDue);
    connect(&m_inner, &Link::bytesReceived, this, [this](const QByteArray& b) {
        if (!m_cut) pass(damage(b, FromDrive), FromDrive);
    });
    connect(&m_inner, &Link::opened, this, &Link::opened);
    connect(&m_inner, &Link::closed, this, &Link::closed);
    connect(&m_inner, &Link::errorOccurred, this, &Link::errorOccurred);
}

void FaultLink::setFaults(Faults toDrive, Faults fromDrive) {
    m_faults[ToDrive] = toDrive;
    m_faults[FromDrive] = fromDrive;
}

void FaultLink::write(const QByteArray& bytes) {
    if (m_cut) {
        emit errorOccurred(tr("the cable is disconnected: nothing was sent"));
        return;
    }
    pass(damage(bytes, ToDrive), ToDrive);
}

void FaultLink::cut() {
    if (m_cut) return;
    m_cut = true;
    m_pending.clear();
    emit errorOccurred(tr("%1: the connection was lost (cable disconnected)").arg(m_inner.description()));
    emit closed();
}

QByteArray FaultLink::damage(const QByteArray& bytes, Direction direction) {
    const Faults& f = m_faults[direction];
    Counters& c = m_counters[direction];
    std::uniform_real_distribution<double> chance(0.0, 1.0);
    std::uniform_int_distribution<int> bit(0, 7);
    QByteArray out;
    out.reserve(bytes.size());
    for (char byte : bytes) {
        ++c.bytes;
        if (f.drop > 0 && chance(m_random) < f.drop) {
            ++c.dropped;
            continue;
        }
        if (f.corrupt > 0 && chance(m_random) < f.corrupt) {
            byte = char(byte ^ (1 << bit(m_random)));
            ++c.corrupted;
        }
        out.append(byte);
        if (f.duplicate > 0 && chance(m_random) < f.duplicate) {
            out.append(byte);
            ++c.duplicated;
        }
    }
    return out;
}

void FaultLink::pass(QByteArray bytes, Direction direction) {
    if (bytes.isEmpty()) return;
    const Faults& f = m_faults[direction];
    qint64 delay = f.delayMs;
    if (f.stall > 0 && std::uniform_real_distribution<double>(0.0, 1.0)(m_random) < f.stall) {
        delay += f.stallMs;
        ++m_counters[direction].stalled;
    }
    const bool queued = std::any_of(m_pending.begin(), m_pending.end(),
                                    [direction](const Pending& p) { return p.direction == direction; });
    if (delay == 0 && !queued) {
        if (direction == ToDrive)
            m_inner.write(bytes);
        else
            emit bytesReceived(bytes);
        return;
    }
    // Order is kept per direction: nothing overtakes a chunk held back before it.
    qint64 due = m_clock.elapsed() + delay;
    for (const Pending& p : m_pending)
        if (p.direction == direction) due = std::max(due, p.dueMs);
    m_pending.push_back({due, std::move(bytes), direction});
    deliverDue();
}

void FaultLink::deliverDue() {
    const qint64 now = m_clock.elapsed();
    while (!m_pending.empty() && !m_cut) {
        auto it = std::min_element(m_pending.begin(), m_pending.end(),
                                   [](const Pending& a, const Pending& b) { return a.dueMs < b.dueMs; });
        if (it->dueMs > now) {
            m_timer.start(int(it->dueMs - now));
            return;
        }
        Pending p = std::move(*it);
        m_pending.erase(it);
        if (p.direction == ToDrive)
            m_inner.write(p.bytes);
        else
            emit bytesReceived(p.bytes);
    }
}

} // namespace serialport
