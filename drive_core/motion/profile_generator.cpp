// Trapezoidal and S-curve profiles from acceleration segments.
#include "profile_generator.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace drive_core::motion {

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kMinTraverse_s = 0.001; // a triangular move keeps a short traverse: 3 segments (BDS5 §7.3)
} // namespace

std::vector<Segment> ProfileGenerator::plan(double from, const MoveRequest& move) {
    const double distance = move.target_counts - from;
    const double direction = distance < 0 ? -1.0 : 1.0;
    const double d = std::abs(distance);
    const double a = move.accel_cps2;
    const double b = move.decel_cps2;
    double v = std::abs(move.velocity_cps);
    if (d == 0 || v == 0) return {};
    // Distance to reach v and stop again; if that is more than the move, the peak speed is lower and the
    // move triangular, keeping a short traverse: d = vp²/2a + vp²/2b + vp·tc.
    const double k = 1 / (2 * a) + 1 / (2 * b);
    double cruise = 0;
    if (k * v * v + v * kMinTraverse_s >= d) {
        v = (-kMinTraverse_s + std::sqrt(kMinTraverse_s * kMinTraverse_s + 4 * k * d)) / (2 * k);
        cruise = kMinTraverse_s;
    } else {
        cruise = (d - k * v * v) / v;
    }
    return {Segment{v / a, direction * a, 1, move.shape}, Segment{cruise, 0, 2},
            Segment{v / b, -direction * b, 3, move.shape}};
}

std::optional<int> ProfileGenerator::push(const MoveRequest& move) {
    if (full()) return std::nullopt;
    Motion m;
    m.id = m_nextId++;
    m.request = move;
    if (!m_active)
        begin(std::move(m));
    else
        m_pending.push_back(std::move(m));
    return m_nextId - 1;
}

int ProfileGenerator::jog(const MoveRequest& jog) {
    m_pending.clear();
    Motion m;
    m.id = m_nextId++;
    m.request = jog;
    // Speeding up uses ACC, slowing down DEC; a reversal uses the smaller of the two (BDS5 §7.4).
    const double target = jog.velocity_cps;
    const double change = target - m_velocity;
    const bool reversing = (m_velocity > 0 && target < 0) || (m_velocity < 0 && target > 0);
    const bool faster = std::abs(target) > std::abs(m_velocity);
    const double rate = reversing ? std::min(jog.accel_cps2, jog.decel_cps2) : faster ? jog.accel_cps2 : jog.decel_cps2;
    const double ramp = std::abs(change) / rate;
    m.segments = {Segment{ramp, change < 0 ? -rate : rate, 1, jog.shape}};
    if (target != 0) m.segments.push_back(Segment{kInfinity, 0, 2});
    m.segmentStartPosition = m_position;
    m.segmentStartVelocity = m_velocity;
    m_active = std::move(m);
    return m_nextId - 1;
}

int ProfileGenerator::start(std::vector<Segment> segments, std::optional<double> endPosition) {
    m_pending.clear();
    Motion m;
    m.id = m_nextId++;
    m.request.kind = endPosition ? MoveKind::Position : MoveKind::Jog;
    m.request.target_counts = endPosition.value_or(0);
    m.segments = std::move(segments);
    m.planned = true;
    m.segmentStartPosition = m_position;
    m.segmentStartVelocity = m_velocity;
    if (m.segments.empty()) {
        m_active.reset();
        if (endPosition) m_position = *endPosition;
        m_velocity = 0;
    } else {
        m_active = std::move(m);
    }
    return m_nextId - 1;
}

std::optional<int> ProfileGenerator::push(std::vector<Segment> segments, double endOffset) {
    if (full()) return std::nullopt;
    Motion m;
    m.id = m_nextId++;
    m.request.kind = MoveKind::Position;
    m.segments = std::move(segments);
    m.planned = true;
    m.endOffset = endOffset;
    if (!m_active)
        begin(std::move(m));
    else
        m_pending.push_back(std::move(m));
    return m_nextId - 1;
}

void ProfileGenerator::stop(double decel_cps2) {
    m_pending.clear();
    if (!m_active || m_velocity == 0) {
        m_active.reset();
        m_velocity = 0;
        return;
    }
    Motion m;
    m.id = m_active->id; // S ends the motion in progress; it is no new command for W
    m.segments = {Segment{std::abs(m_velocity) / decel_cps2, m_velocity > 0 ? -decel_cps2 : decel_cps2, 3}};
    m.segmentStartPosition = m_position;
    m.segmentStartVelocity = m_velocity;
    // A stop is a position move to where the ramp ends (it must not "land" on a default target).
    m.request.target_counts = m_position + m_velocity * std::abs(m_velocity) / (2 * decel_cps2);
    m_active = std::move(m);
}

void ProfileGenerator::setPosition(double counts) {
    m_position = counts;
}

void ProfileGenerator::begin(Motion motion) {
    if (motion.planned)
        motion.request.target_counts = m_position + motion.endOffset;
    else
        motion.segments = plan(m_position, motion.request);
    motion.segmentStartPosition = m_position;
    motion.segmentStartVelocity = 0;
    if (motion.segments.empty()) { // nothing to do: the move is over as it starts
        m_position = motion.request.target_counts;
        m_active.reset();
        return;
    }
    m_active = std::move(motion);
}

void ProfileGenerator::startNext() {
    m_active.reset();
    m_velocity = 0;
    while (!m_active && !m_pending.empty()) {
        Motion next = std::move(m_pending.front());
        m_pending.pop_front();
        begin(std::move(next));
    }
}

void ProfileGenerator::step(double dt_s) {
    if (m_held) return;
    double left = dt_s;
    while (m_active && left > 0) {
        Motion& m = *m_active;
        const Segment& s = m.segments[m.index];
        const double remaining = s.duration_s - m.elapsed_s;
        const double t = std::min(left, remaining);
        m.elapsed_s += t;
        left -= t;
        const double e = m.elapsed_s;
        if (s.shape == SCurve::Straight || s.accel_cps2 == 0 || !(s.duration_s > 0)) {
            m_position = m.segmentStartPosition + m.segmentStartVelocity * e + 0.5 * s.accel_cps2 * e * e;
            m_velocity = m.segmentStartVelocity + s.accel_cps2 * e;
        } else { // the same velocity change and distance as a straight line, shaped (s_curve.h)
            const double T = s.duration_s, tau = e / T;
            m_position = m.segmentStartPosition + m.segmentStartVelocity * e +
                         s.accel_cps2 * T * T * sCurvePosition(s.shape, tau);
            m_velocity = m.segmentStartVelocity + s.accel_cps2 * T * sCurveVelocity(s.shape, tau);
        }
        if (m.elapsed_s < s.duration_s) break;
        // The segment is over: the next starts exactly where it ended.
        m.segmentStartPosition = m_position;
        m.segmentStartVelocity = m_velocity;
        m.elapsed_s = 0;
        if (++m.index < m.segments.size()) continue;
        if (m.request.kind == MoveKind::Position) m_position = m.request.target_counts; // exact landing
        startNext();
    }
}

double ProfileGenerator::acceleration() const {
    if (!m_active) return 0;
    const Segment& s = m_active->segments[m_active->index];
    if (s.shape == SCurve::Straight || s.accel_cps2 == 0 || !(s.duration_s > 0)) return s.accel_cps2;
    return s.accel_cps2 * sCurveAcceleration(s.shape, m_active->elapsed_s / s.duration_s);
}

int ProfileGenerator::segment() const {
    return m_active ? m_active->segments[m_active->index].number : 0;
}

double ProfileGenerator::finalPosition() const {
    if (!m_pending.empty()) { // pending moves are position moves; planned ones end relative to the one before
        double end =
            m_active && m_active->request.kind == MoveKind::Position ? m_active->request.target_counts : m_position;
        for (const Motion& p : m_pending) end = p.planned ? end + p.endOffset : p.request.target_counts;
        return end;
    }
    if (m_active && m_active->request.kind == MoveKind::Position) return m_active->request.target_counts;
    return m_position;
}

bool ProfileGenerator::reached(int id, int segment) const {
    if (!m_active) return true;          // W never waits when motion has stopped
    if (segment == 0) return false;      // W 0: until motion has stopped
    if (m_active->id > id) return true;  // that motion is over, a later one runs
    if (m_active->id < id) return false; // that motion is still pending
    return this->segment() >= segment;
}

} // namespace drive_core::motion
