// Measures the simulated BDS5's loops the way an engineer with a signal analyser would: a sine sweep on
// the velocity command (closed-loop bandwidth) and a position step (overshoot), on a Bds5Servo of its own.
#pragma once

#include "drive_core/bds5/bds5_servo.h"
#include "drive_core/bds5/bds5_variable_store.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace bds5_test {

struct LoopGains {
    double kv = 2000, kvi = 5000, kp = 1500;
};

// |VFB / VCMD| at f_Hz for a velocity loop (PL off) with a sine of amp_cps (300 RPM by default: well above
// the Coulomb friction, well below saturation), taken from the fundamental over whole cycles.
inline double velocityGain(const LoopGains& g, double f_Hz, const drive_core::physics::LoadParameters& load = {},
                           double amp_cps = 20000) {
    drive_core::bds5::Bds5VariableStore vars;
    vars.set("PL", 0);
    vars.set("KV", std::int32_t(std::lround(g.kv)));
    vars.set("KVI", std::int32_t(std::lround(g.kvi)));
    drive_core::bds5::Bds5Servo servo;
    servo.setLoad(load);
    const double period_ms = 1000 / f_Hz;
    const int start = int(std::ceil(0.3 * f_Hz) * period_ms);
    const int end = start + int((std::ceil(0.5 * f_Hz) + 2) * period_ms);
    double ys = 0, yc = 0, xs = 0, xc = 0;
    for (int k = 0; k < end; ++k) {
        const double phase = 2 * std::numbers::pi * f_Hz * k * 1e-3;
        const double command = amp_cps * std::sin(phase);
        servo.tick(0, command, true, vars);
        if (k < start) continue;
        ys += servo.velocity_cps() * std::sin(phase);
        yc += servo.velocity_cps() * std::cos(phase);
        xs += command * std::sin(phase);
        xc += command * std::cos(phase);
    }
    return std::hypot(ys, yc) / std::hypot(xs, xc);
}

// The -3 dB frequency of the velocity loop, by bisection on the sweep.
inline double velocityBandwidth_Hz(const LoopGains& g, const drive_core::physics::LoadParameters& load = {}) {
    double lo = 0.5, hi = 500;
    for (int i = 0; i < 30; ++i) {
        const double mid = std::sqrt(lo * hi);
        (velocityGain(g, mid, load) > std::sqrt(0.5) ? lo : hi) = mid;
    }
    return lo;
}

// The overshoot of PFB (a fraction of the step) after a position step of step_counts, KF 0, over 3 s.
inline double positionOvershoot(const LoopGains& g, double step_counts) {
    drive_core::bds5::Bds5VariableStore vars;
    vars.set("KV", std::int32_t(std::lround(g.kv)));
    vars.set("KVI", std::int32_t(std::lround(g.kvi)));
    vars.set("KP", std::int32_t(std::lround(g.kp)));
    vars.set("KF", 0);
    drive_core::bds5::Bds5Servo servo;
    double highest = 0;
    for (int k = 0; k < 3000; ++k) {
        servo.tick(step_counts, 0, true, vars);
        highest = std::max(highest, double(servo.feedback_counts()));
    }
    return (highest - step_counts) / step_counts;
}

// The inertia on the shaft of a default servo (motor + load).
inline double defaultInertia_kgm2() {
    const drive_core::bds5::Bds5Servo servo;
    return servo.plant().motor().rotorInertia_kgm2 + servo.plant().load().inertia_kgm2;
}

} // namespace bds5_test
