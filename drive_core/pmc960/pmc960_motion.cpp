// PMC-960 motion: the reference, the PSJ and the modes around the servo loops.
#include "pmc960_motion.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace drive_core::pmc960 {

void Pmc960Motion::reset() {
    m_generator = motion::ProfileGenerator{};
    m_sensorAction = SensorAction::None;
    m_cam = false;
    m_camPending.reset();
    m_mode = 0;
    m_psj = 0;
    m_overflow = false;
    m_forward = true;
    m_fps = false;
    m_fpsArmed = false;
    m_due_us = 0;
    m_servo.resetIntegrators();
    m_servo.setCount(0); // the absolute position counts from 0 at power-up, the shaft where it is
    m_feedback_counts = 0;
    resyncReference();
}

// SM3 leaves the PSJ alone: its count acts at once and the motor jumps to cancel it (L1592-1593). It does
// not clear an overflow either (only SM1 or SM2 do, L2382), so after one it trips again at once.
void Pmc960Motion::setMode(int mode) {
    if (mode == 0) {
        m_fps = false;
        sharpStop(); // the reference stops where it is; the disabled servodrive brakes the motor (S9); the
                     // PSJ keeps its count and goes on counting the feedback
    } else if (mode == 1 || mode == 2) { // the PSJ is cleared (SM1: not summed), and an overflow with it
        // SM2 at rest without an overflow: the absolute position takes up the error (L1589-1590), so the
        // reference is where the motor is; in motion or after an overflow the position is not adjusted.
        if (mode == 2 && !moving() && !m_overflow) {
            m_generator.setPosition(actual_counts());
            resyncReference();
        }
        m_psj = 0;
        m_overflow = false;
        m_servo.resetIntegrators();
    }
    m_mode = mode;
}

void Pmc960Motion::index(double distance_counts, double velocity_cps, double accel_cps2) {
    (void)go(m_generator.finalPosition() + distance_counts, velocity_cps, accel_cps2);
}

bool Pmc960Motion::go(double target_counts, double velocity_cps, double accel_cps2) {
    motion::MoveRequest move;
    move.kind = motion::MoveKind::Position;
    move.target_counts = target_counts;
    move.velocity_cps = velocity_cps;
    move.accel_cps2 = accel_cps2;
    move.decel_cps2 = accel_cps2;
    if (target_counts != m_generator.position()) m_forward = target_counts > m_generator.position();
    return m_generator.push(move).has_value();
}

void Pmc960Motion::jog(double velocity_cps, double accel_cps2) {
    motion::MoveRequest move;
    move.kind = motion::MoveKind::Jog;
    move.velocity_cps = velocity_cps;
    move.accel_cps2 = accel_cps2;
    move.decel_cps2 = accel_cps2;
    if (velocity_cps != 0) m_forward = velocity_cps > 0;
    m_cam = false; // a jog takes over from a cam holding its speed
    m_camPending.reset();
    m_generator.jog(move);
}

void Pmc960Motion::setPositiveStop(std::optional<double> position_counts) {
    m_stop_counts = position_counts;
    if (position_counts) m_stopAhead = *position_counts >= m_servo.position_counts();
}

void Pmc960Motion::stop(double decel_cps2) {
    if (m_fps) { // ends FPS: torque off, the absolute position corrected, PSJ reset, the loop closed (L1684)
        m_fps = false;
        m_generator.setPosition(actual_counts());
        resyncReference();
        m_psj = 0;
        m_servo.resetIntegrators();
        return;
    }
    m_generator.setHeld(false); // a stop also cancels a start still waiting for SENSOR
    m_sensorAction = SensorAction::None;
    m_cam = false;
    m_camPending.reset();
    m_generator.stop(decel_cps2);
}

void Pmc960Motion::sharpStop() {
    const double here = m_generator.position();
    m_sensorAction = SensorAction::None;
    m_cam = false;
    m_camPending.reset();
    m_generator = motion::ProfileGenerator{};
    m_generator.setPosition(here);
    resyncReference();
}

double Pmc960Motion::normalize(double position_counts) {
    const double cancelled = double(m_psj);
    m_generator.setPosition(position_counts);
    resyncReference();
    m_servo.setCount(std::llround(position_counts));
    m_feedback_counts = m_servo.count();
    m_psj = 0;
    return cancelled;
}

void Pmc960Motion::onSensor(SensorAction action, double decel_cps2, double depth_counts) {
    m_sensorAction = action;
    m_sensorDecel_cps2 = std::max(1.0, decel_cps2);
    m_depth_counts = depth_counts;
}

void Pmc960Motion::sensor() {
    if (m_generator.held()) { // external start: the motion begins; this edge does nothing else
        m_generator.setHeld(false);
        return;
    }
    if (m_sensorAction == SensorAction::None || !moving()) return;
    // EXTERNAL DECEL and ADAPTIVE DEPTH look for SENSOR only once top speed is reached (L1487-1492, L1622).
    if (m_sensorAction != SensorAction::Stop && !atTopSpeed()) return;
    const SensorAction action = m_sensorAction;
    m_sensorAction = SensorAction::None;
    const double v = m_generator.velocity();
    const double a = m_sensorDecel_cps2;
    if (action != SensorAction::Depth || v == 0) {
        m_generator.stop(a);
        return;
    }
    // Stop depth counts past SENSOR: cruise, then decelerate at a, landing exactly on the spot.
    const double speed = std::abs(v);
    const double direction = v > 0 ? 1.0 : -1.0;
    const double cruise_s = std::max(0.0, (m_depth_counts - speed * speed / (2 * a)) / speed);
    std::vector<motion::Segment> plan;
    if (cruise_s > 0) plan.push_back({cruise_s, 0.0});
    plan.push_back({speed / a, -direction * a});
    const double travel = speed * cruise_s + speed * speed / (2 * a);
    m_generator.start(std::move(plan), m_generator.position() + direction * travel);
}

double Pmc960Motion::steadyError_counts(double velocity_cps) const {
    const double kv = m_servo.positionLoopGain_perS();
    if (kv <= 0) return 1e12; // no position loop: no steady error to speak of
    return std::abs(velocity_cps) * std::abs(1 - m_servo.feedForwardShare()) / kv;
}

double Pmc960Motion::remaining_counts() const {
    return std::abs(m_generator.finalPosition() - m_generator.position());
}

bool Pmc960Motion::step(double dt_s) {
    m_due_us += std::llround(dt_s * 1e6);
    while (m_due_us >= Pmc960Servo::kPeriod_us) {
        m_due_us -= Pmc960Servo::kPeriod_us;
        if (servoTick()) return true;
    }
    return false;
}

bool Pmc960Motion::servoTick() {
    constexpr double period = Pmc960Servo::kPeriod_s;
    // The reference generator runs on the crystal, or in slave mode on the master's pulses (S11).
    double referenceTime_s = period;
    if (m_slave) referenceTime_s = std::max(0.0, m_master.advance(period)) / m_servo.gains().rangeTop_cps;
    if (referenceTime_s > 0) m_generator.step(referenceTime_s);
    if (!moving()) m_sensorAction = SensorAction::None;
    if (m_camPending && (!moving() || m_generator.segment() == 2)) { // the ramp before it has ended
        const CamSegment next = *m_camPending;
        m_camPending.reset();
        (void)startCam(next, false);
    }
    if (!moving()) m_cam = false;

    const std::int64_t reference = std::llround(m_generator.position());
    if (m_mode != 1) m_psj += reference - m_reference_counts; // SM1: not summed (L217)
    m_reference_counts = reference;

    using Loop = Pmc960Servo::Loop;
    Loop loop = Loop::Off;
    if (m_mode == 1) loop = Loop::Velocity;
    if (m_mode >= 2) loop = m_fps ? Loop::Torque : Loop::Position;
    if (m_mode >= 2 && m_overflow) loop = Loop::Off; // SM3 after an overflow trips before the loop closes
    const double referenceVelocity = m_generator.velocity() * referenceTime_s / period;
    m_servo.tick(loop, double(m_psj), referenceVelocity, (m_forward ? 1 : -1) * m_stopTorque);
    if (m_stop_counts &&
        (m_stopAhead ? m_servo.position_counts() > *m_stop_counts : m_servo.position_counts() < *m_stop_counts))
        m_servo.stallAt(*m_stop_counts); // the motor stalls on the stop; the reference runs on into the PSJ

    const std::int64_t feedback = m_servo.count();
    if (m_mode != 1) m_psj -= feedback - m_feedback_counts;
    m_feedback_counts = feedback;

    if (m_mode < 2) return false; // SF trips only in a position mode (L221-223)
    if (m_overflow) return true;
    if (m_fps) return false; // torque against the stop: no position or velocity loop
    if (!moving()) m_fpsArmed = false;
    const bool beyond = double(std::abs(m_psj)) > m_trip_counts;
    if (beyond && m_fpsArmed) { // at the stop: hold torque (L1676-1680)
        m_fpsArmed = false;
        m_fps = true;
        sharpStop();
        return false;
    }
    if (beyond) m_overflow = true; // the caller snapshots, then SM0
    return m_overflow;
}

} // namespace drive_core::pmc960
