// SC750 motion commands on the shared profile generator (see sc750_motion.h).
#include "sc750_motion.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace drive_core::sc750 {

namespace {
constexpr double kInstant = 1e12; // counts/s²: a stop that takes no time
double rate(double rpmPerS) {
    return std::max(1.0, rpmPerS) * kCpsPerRpm;
}
} // namespace

void Sc750Motion::goVel(const MoveSettings& s) {
    m_positionMove = false;
    motion::MoveRequest jog;
    jog.kind = motion::MoveKind::Jog;
    jog.velocity_cps = std::max(0.0, s.speed_rpm) * kCpsPerRpm * (s.dir == 1 ? -1 : 1);
    jog.accel_cps2 = rate(s.accel_rpm_per_s);
    jog.decel_cps2 = rate(s.decel_rpm_per_s);
    if (!s.sCurve) {
        m_generator.jog(jog);
        return;
    }
    // the generator's jog rule (BDS5 §7.4), ramped as an S-curve
    const double v0 = m_generator.velocity();
    const double target = jog.velocity_cps;
    const bool reversing = (v0 > 0 && target < 0) || (v0 < 0 && target > 0);
    const bool faster = std::abs(target) > std::abs(v0);
    const double a = reversing ? std::min(jog.accel_cps2, jog.decel_cps2) : faster ? jog.accel_cps2 : jog.decel_cps2;
    std::vector<motion::Segment> segments{{std::abs(target - v0) / a, target < v0 ? -a : a, 1}};
    if (target != 0) segments.push_back({std::numeric_limits<double>::infinity(), 0, 2});
    m_generator.start(shaped(segments), std::nullopt);
}

std::vector<motion::Segment> Sc750Motion::shaped(const std::vector<motion::Segment>& segments) {
    constexpr int kSCurveSteps = 16;
    std::vector<motion::Segment> out;
    for (const motion::Segment& seg : segments) {
        if (seg.accel_cps2 == 0 || !std::isfinite(seg.duration_s) || seg.duration_s <= 0) {
            out.push_back(seg);
            continue;
        }
        for (int k = 0; k < kSCurveSteps; ++k) { // midpoints of a triangle: their mean is exactly 1
            const double x = (k + 0.5) / kSCurveSteps;
            const double weight = 2 * (x < 0.5 ? 2 * x : 2 * (1 - x));
            out.push_back({seg.duration_s / kSCurveSteps, seg.accel_cps2 * weight, seg.number});
        }
    }
    return out;
}

void Sc750Motion::goAbs(double target_counts, const MoveSettings& s) {
    moveTo(target_counts - m_offset_counts - m_gear_counts, s);
}

// The gear's speed ramps to the master's at ACCEL.GEAR, accumulating the lag in GEARERROR, then follows it
// exactly (GEARLOCK); switched off, it ramps to rest at DECEL.GEAR.
void Sc750Motion::stepGearing(double dt_s, const GearSettings& g) {
    double target = 0;
    if (g.mode != 0) {
        const double master = g.mode == 2   ? std::max(0.0, g.master_cps)
                              : g.mode == 3 ? std::min(0.0, g.master_cps)
                                            : g.master_cps;
        target = master * g.counts_per_master_count;
    }
    if (g.mode != 0 && m_gearLocked) {
        m_gearVelocity_cps = target;
    } else {
        const double most = rate(g.mode != 0 ? g.accel_rpm_per_s : g.decel_rpm_per_s) * dt_s;
        const double before = m_gearVelocity_cps;
        m_gearVelocity_cps = before + std::clamp(target - before, -most, most);
        if (g.mode != 0) m_gearError_counts += (target - (before + m_gearVelocity_cps) / 2) * dt_s;
        m_gearLocked = g.mode != 0 && m_gearVelocity_cps == target;
    }
    m_gear_counts += m_gearVelocity_cps * dt_s;
}

void Sc750Motion::goIncr(double distance_counts, const MoveSettings& s) {
    const double from = m_positionMove && moving() ? m_target : m_generator.position();
    // (gearing, superimposed, is not part of the profile: a GEARERROR correction is a plain increment)
    moveTo(from + distance_counts, s);
}

void Sc750Motion::abort(double decel_rpm_per_s) {
    m_generator.stop(rate(decel_rpm_per_s));
    m_positionMove = false;
}

void Sc750Motion::halt() {
    m_generator.stop(kInstant);
    m_positionMove = false;
}

void Sc750Motion::update(const MoveSettings& s) {
    if (!moving()) return;
    if (m_positionMove)
        moveTo(m_target, s);
    else if (!m_generator.jogging())
        return; // a stop in progress keeps its deceleration
    else
        goVel(s);
}

// A position move from the present position and speed: brake first if moving away or too fast to stop
// in time, then accelerate / cruise / decelerate to land on the target (digest §7.3 moving-start plan).
void Sc750Motion::moveTo(double target, const MoveSettings& s) {
    m_positionMove = true;
    m_target = target;
    const double a = rate(s.accel_rpm_per_s);
    const double d = rate(s.decel_rpm_per_s);
    const double vmax = std::max(1e-6, s.speed_rpm * kCpsPerRpm);
    const double p0 = m_generator.position();
    const double v0 = m_generator.velocity();
    std::vector<motion::Segment> segments;
    double p = p0, v = v0;
    const double distance = target - p0;
    const double dir = distance > 0 ? 1.0 : distance < 0 ? -1.0 : (v0 > 0 ? -1.0 : 1.0);
    const bool away = v0 * dir < 0;
    const bool overshoot = !away && v0 * v0 / (2 * d) > std::abs(distance);
    if (v0 != 0 && (away || overshoot)) {
        const double t = std::abs(v0) / d;
        segments.push_back({t, v0 > 0 ? -d : d, 3});
        p = p0 + v0 * t / 2;
        v = 0;
    }
    const double remaining = target - p;
    if (remaining == 0 && v == 0) {
        m_generator.start(s.sCurve ? shaped(segments) : std::move(segments), target);
        return;
    }
    const double sgn = remaining >= 0 ? 1.0 : -1.0;
    const double dist = std::abs(remaining);
    double u = std::abs(v); // in the direction of travel
    if (u > vmax) {         // faster than the new speed: slow down to it first
        segments.push_back({(u - vmax) / d, -sgn * d, 3});
        const double used = (u * u - vmax * vmax) / (2 * d);
        const double cruise = std::max(0.0, dist - used - vmax * vmax / (2 * d)) / vmax;
        segments.push_back({cruise, 0, 2});
        segments.push_back({vmax / d, -sgn * d, 3});
        m_generator.start(s.sCurve ? shaped(segments) : std::move(segments), target);
        return;
    }
    double vp = std::sqrt((dist + u * u / (2 * a)) / (1 / (2 * a) + 1 / (2 * d)));
    double cruise = 0;
    if (vp > vmax) {
        vp = vmax;
        cruise = (dist - (vmax * vmax - u * u) / (2 * a) - vmax * vmax / (2 * d)) / vmax;
    }
    segments.push_back({(vp - u) / a, sgn * a, 1});
    segments.push_back({std::max(0.0, cruise), 0, 2});
    segments.push_back({vp / d, -sgn * d, 3});
    m_generator.start(s.sCurve ? shaped(segments) : std::move(segments), target);
}

} // namespace drive_core::sc750
