// TUNE: the shake, the inertia estimate and the gains.
#include "bds5_tune.h"

#include "bds5_loop_scaling.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace drive_core::bds5 {

namespace ls = loop_scaling;

namespace {
constexpr double kShake_Hz = 15;             // "shakes the motor at about 15 Hz and at full torque" (L6252)
constexpr int kShakeCycles = 4;              // the first is discarded (the current loop and friction settle)
constexpr double kMaxGain = 32767;           // KV, KPROP, KP, KVI are 1..32767 (ShortPositive)
constexpr double kLpfPerBandwidth = 5;       // a two-pole LPF below 5 x the bandwidth eats the phase margin
constexpr double kResonancePerBandwidth = 4; // a compliant coupling's resonance must lie well above it
constexpr double kBasicPerCps = 65.536;

// The -3 dB bandwidth of wn^2 / (s^2 + 2 zeta wn s + wn^2), as a fraction of wn.
double bandwidthPerWn(double zeta) {
    const double b = 1 - 2 * zeta * zeta;
    return std::sqrt(b + std::sqrt(b * b + 1));
}
} // namespace

bool Bds5Tune::validBandwidth(int bandwidth_Hz) {
    for (const int allowed : {5, 10, 15, 20, 25, 30, 40, 50})
        if (bandwidth_Hz == allowed) return true;
    return false;
}

// chosen: the manual says only "slightly"; 0.8 and 1.25 give about 1.5 % overshoot and a visibly slower
// edge, either side of critical damping.
double Bds5Tune::damping(int stability) {
    switch (stability) {
    case 1: return 1.25;
    case 2: return 1.0;
    case 3: return 0.8;
    default: return 0;
    }
}

// See bds5_loop_scaling.h: KVI' = wn / (2 zeta), a = 2 zeta wn = Kt Ipeak KV' / J. KVI comes from the
// corner through Table 6.3 (whose corners are those of critical damping), KP from Table 6.4 (100 per Hz),
// KPROP so the proportional loop alone (first order) reaches the bandwidth.
TuneGains Bds5Tune::gainsFor(double bandwidth_Hz, double damping, double inertia_kgm2, double torqueConstant_NmPerA,
                             double peakCurrent_A) {
    const double wn = 2 * std::numbers::pi * bandwidth_Hz / bandwidthPerWn(damping);
    const double corner = wn / (2 * damping);
    const double equivalent_Hz = corner * 2 * ls::kCriticalBandwidthPerWn / (2 * std::numbers::pi);
    const double perGain = torqueConstant_NmPerA * peakCurrent_A * ls::kKvFractionPerRadPerS / inertia_kgm2;
    TuneGains g;
    g.kvi = ls::kviForBandwidth(equivalent_Hz);
    g.kv = 2 * damping * wn / perGain;
    g.kp = 100 * bandwidth_Hz;
    g.kprop = 2 * std::numbers::pi * bandwidth_Hz / perGain;
    return g;
}

double Bds5Tune::measureInertia(Bds5Servo& servo, Bds5VariableStore& vars) {
    physics::Plant& plant = servo.plant();
    const double peak = plant.motor().peakCurrent_A;
    const double current = std::clamp(double(vars.read("ILIM").value_or(4095)) / 4095, 0.01, 1.0) * peak;
    const double vospd_radPerS =
        double(vars.read(*catalog::bds5::findVariable("VOSPD"))) / kBasicPerCps / kCountsPerRev * 2 * std::numbers::pi;
    const int halfPeriod_ms = int(std::lround(1000 / kShake_Hz / 2));
    // A first quarter-length push so the speed swings symmetrically about zero.
    double impulse = 0, swing = 0, sign = 1;
    double start = plant.motorSpeed_radPerS();
    for (int half = 0; half < 2 * kShakeCycles + 1; ++half) {
        const int length = half == 0 ? halfPeriod_ms / 2 : halfPeriod_ms;
        double charge = 0;
        for (int ms = 0; ms < length; ++ms) {
            plant.step(Bds5Servo::kPeriod_s, sign * current);
            charge += plant.current_A() * Bds5Servo::kPeriod_s;
            if (std::abs(plant.motorSpeed_radPerS()) > vospd_radPerS) {
                servo.settle();
                return -13;
            }
        }
        const double end = plant.motorSpeed_radPerS();
        if (half >= 3) { // after the first full cycle
            impulse += std::abs(charge) * plant.motor().torqueConstant_NmPerA;
            swing += std::abs(end - start);
        }
        start = end;
        sign = -sign;
    }
    // Let the motor coast to rest under a little braking current before the loops take over again.
    for (int ms = 0; ms < 200 && std::abs(plant.motorSpeed_radPerS()) > 1e-3; ++ms)
        plant.step(Bds5Servo::kPeriod_s, -std::clamp(plant.motorSpeed_radPerS() * 0.05, -current, current));
    servo.settle();
    return swing > 0 ? impulse / swing : -20;
}

int Bds5Tune::run(Bds5Servo& servo, Bds5VariableStore& vars, int bandwidth_Hz, int stability, bool remote) {
    if (!remote) return 20; // "REMOTE off" (L7207)
    const physics::Plant& plant = servo.plant();
    // A compliant load resonating near the bandwidth, or an LPF below it, cannot be tuned (L6288-6300).
    if (plant.resonance_Hz() > 0 && plant.resonance_Hz() < kResonancePerBandwidth * bandwidth_Hz) return 20;
    if (vars.read("LPF").value_or(0) != 0 && vars.read("LPFHZ").value_or(0) < kLpfPerBandwidth * bandwidth_Hz)
        return 20;
    const double inertia = measureInertia(servo, vars);
    if (inertia < 0) return int(-inertia);
    const TuneGains g = gainsFor(bandwidth_Hz, damping(stability), inertia, plant.motor().torqueConstant_NmPerA,
                                 plant.motor().peakCurrent_A);
    if (g.kv > kMaxGain || g.kprop > kMaxGain || g.kvi > kMaxGain) return 20; // inertia too large (L7207)
    if (g.kv < 1 || g.kprop < 1) return 20;
    vars.set("KV", std::int32_t(std::lround(g.kv)));
    vars.set("KVI", std::int32_t(std::lround(g.kvi)));
    vars.set("KP", std::int32_t(std::lround(g.kp)));
    vars.set("KPROP", std::int32_t(std::lround(g.kprop)));
    return 0;
}

} // namespace drive_core::bds5
