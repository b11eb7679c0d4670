// The PMC-960's Cam command (7.4, L1093-1117): distance-based changes of speed. A segment ramps the speed
// uniformly over the distance to its position, reaching the new speed there, then holds it until the next
// segment (speed 0 stops at the position). Cam errors 81-86, 89, 8A, 8B (digest §7.1).
#include "pmc960_interpreter.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <vector>

namespace drive_core::pmc960 {

namespace {
constexpr std::int64_t kSpeedDigitsCap = 1'000'000'000'000; // past every range's maximum speed
} // namespace

using CamResult = Pmc960Motion::CamResult;

CamResult Pmc960Motion::cam(double position_counts, double speed_cps, double maxAccel_cps2) {
    if (moving() && !m_cam) return CamResult::OtherMotion;
    const CamSegment segment{position_counts, speed_cps, maxAccel_cps2};
    if (m_cam && m_generator.segment() == 1) { // the running segment is still in its ramp
        if (m_camPending) return CamResult::Full;
        // Checked now against where the ramp ends, so the error answers the command that caused it.
        if (std::abs(position_counts - m_camEnd_counts) < 1) return CamResult::TooClose;
        const double direction = position_counts > m_camEnd_counts ? 1 : -1;
        if ((m_forward ? 1 : -1) != direction) return CamResult::Reverse;
        m_camPending = segment;
        return CamResult::Queued;
    }
    return startCam(segment, true);
}

CamResult Pmc960Motion::startCam(const CamSegment& segment, bool check) {
    const double from = m_generator.position();
    const double v0 = m_generator.velocity();
    const double distance = segment.position_counts - from;
    if (std::abs(distance) < 1) return CamResult::TooClose;
    const double direction = distance > 0 ? 1 : -1;
    if (v0 != 0 && (v0 > 0 ? 1 : -1) != direction) return CamResult::Reverse; // stop at speed 0 first
    const double s0 = std::abs(v0), s1 = segment.speed_cps;
    const double accel = std::abs(s1 * s1 - s0 * s0) / (2 * std::abs(distance));
    const double ramp_s = 2 * std::abs(distance) / (s0 + s1);
    if (check && accel > segment.maxAccel_cps2) return CamResult::AccelTooHigh;
    if (check && ramp_s > kMaxCamRamp_s) return CamResult::RampTooLong;
    std::vector<motion::Segment> plan;
    plan.push_back({ramp_s, direction * (s1 - s0) / ramp_s, 1});
    if (s1 > 0) plan.push_back({INFINITY, 0.0, 2}); // hold the cam speed
    m_forward = direction > 0;
    m_cam = s1 > 0;
    m_camEnd_counts = segment.position_counts;
    m_generator.start(std::move(plan), s1 > 0 ? std::nullopt : std::optional<double>(segment.position_counts));
    return CamResult::Started;
}

// C[<sign>]<position>[:<speed>](<cr>|^) | C^ | C* (L1095-1117, L1684). ^ waits until the segment reaches its
// position. In binary input the position's last byte ends the segment as <cr> would (L1877).
void Pmc960Interpreter::camArgument(char c, bool first) {
    Pmc960Registers& reg = m_state.reg;
    Pmc960Motion& motion = m_state.motion;
    if (first && (c == '+' || c == '-')) {
        m_sign = c == '+' ? 1 : -1;
        return;
    }
    if (first && c == '*') { // C* (c* among the stop commands, L1684) is complete like C^: no <cr> follows
        stopMotion();
        return finish();
    }
    if (first && c == '^') return beginWait(Pmc960Wait::CamSegment, true);
    if (c == ':' && !m_colon && numberGiven()) {
        m_colon = true;
        return;
    }
    if (collectDigit(c, false)) return;
    if (c != '\r' && c != '^') return fail(0xA2);
    if (!numberGiven()) return fail(0xA2);
    std::int64_t speed = reg.camSpeed;
    if (m_colon) {
        speed = 0;
        for (const char d : m_fraction) {
            if (!std::isdigit(static_cast<unsigned char>(d))) return fail(0xA2);
            // Capped far above any speed the controller takes (#94 below), never overflowing
            // (pmc960_drive_fuzz finding: twenty digits after the colon).
            speed = std::min<std::int64_t>(speed * 10 + (d - '0'), kSpeedDigitsCap);
        }
    } else if (!motion.camRunning()) {
        return fail(0x81); // the previous speed is a running cam's: no cam, no change (chosen)
    }
    const Pmc960Units units = m_state.units();
    if (speed > std::int64_t(units.maximumUserVelocity())) return fail(0x94);
    if (units.velocityTooSmall(double(speed))) return fail(0x98);
    if (units.positionOverflows(double(number()), double(std::int64_t(1) << 30))) return fail(0x99);
    if (speed == 0 && !motion.moving()) return fail(0x8B); // from rest to rest: nothing to ramp
    const double target = units.position_counts(double((m_sign < 0 ? -1 : 1) * number()));
    if (!motionAllowed(target < motion.commanded_counts())) return;
    const double feedrate = double(reg.feedrate) / 100.0;
    switch (
        motion.cam(target, units.velocity_cps(double(speed)) * feedrate, units.accel_cps2(double(reg.acceleration)))) {
    case CamResult::Started:
    case CamResult::Queued: break;
    case CamResult::Full: return fail(0x8A);
    case CamResult::OtherMotion: return fail(0x84);
    case CamResult::Reverse: return fail(0x82);
    case CamResult::TooClose: return fail(0x85);
    case CamResult::AccelTooHigh: return fail(0x86);
    case CamResult::RampTooLong: return fail(0x83);
    }
    reg.camSpeed = speed;
    if (c == '^') return beginWait(Pmc960Wait::CamSegment, true);
    finish();
}

} // namespace drive_core::pmc960
