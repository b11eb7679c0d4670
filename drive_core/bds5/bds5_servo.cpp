// The BDS5's 1 ms servo loops on the simulated plant.
#include "bds5_servo.h"

#include "bds5_loop_scaling.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace drive_core::bds5 {

namespace cat = catalog::bds5;
namespace ls = loop_scaling;

namespace {
constexpr double kFullCurrent = 4095;   // basic current units: 4095 = IMAX = 100 % (L1538)
constexpr double kBasicPerCps = 65.536; // basic velocity: 1/65536 count per ms
constexpr double kFoldHigh = 1.5;       // IFOLD "well above IMAX" at rest and when disabled (L2143)
constexpr double kCountsPerRad = kCountsPerRev / (2 * std::numbers::pi);
constexpr double kRadPerCount = 1 / kCountsPerRad;

// The variables the loop reads and writes every millisecond, resolved once to their slots.
using Slot = Bds5VariableStore::Slot;
struct Refs {
    Slot kp, kf, kv, kvi, kprop, pl, prop, tq, lpf, lpfhz, ilim, icont, pemax, vospd, foldt, foldr;
    Slot pfb, prd, pe, vfb, vavg, ve, icmd, imon, ifold, sat, fold;
};
const Refs& refs() {
    static const Refs r = [] {
        const auto f = [](const char* name) {
            return Bds5VariableStore::slotOf(cat::findVariable(name).value_or(cat::VariableRef{}));
        };
        return Refs{f("KP"),    f("KF"),    f("KV"),    f("KVI"),   f("KPROP"), f("PL"),    f("PROP"),
                    f("TQ"),    f("LPF"),   f("LPFHZ"), f("ILIM"),  f("ICONT"), f("PEMAX"), f("VOSPD"),
                    f("FOLDT"), f("FOLDR"), f("PFB"),   f("PRD"),   f("PE"),    f("VFB"),   f("VAVG"),
                    f("VE"),    f("ICMD"),  f("IMON"),  f("IFOLD"), f("SAT"),   f("FOLD")};
    }();
    return r;
}
double get(const Bds5VariableStore& vars, Slot ref) {
    return ref.valid() ? double(vars.read(ref)) : 0.0;
}
void put(Bds5VariableStore& vars, Slot ref, double value) {
    if (ref.valid()) vars.set(ref, std::int32_t(std::lrint(std::clamp(value, double(INT32_MIN), double(INT32_MAX)))));
}
} // namespace

Bds5Servo::Bds5Servo() : m_plant(physics::MotorParameters{}, physics::LoadParameters{}) {
    powerUp();
}

void Bds5Servo::setMotor(const physics::MotorParameters& motor) {
    m_plant = physics::Plant(motor, m_plant.load());
    powerUp();
}

void Bds5Servo::powerUp() {
    m_offset_counts = -resolverCount(); // PFB is 0 at power-up (Table 3.2)
    m_feedback_counts = 0;
    m_lastAngle_rad = m_plant.motorAngle_rad();
    m_angleHistory.fill(m_lastAngle_rad);
    m_velocity_cps = 0;
    m_integral_radPerS = 0;
    m_lpf = {};
    m_ifold = kFoldHigh;
}

void Bds5Servo::settle() {
    m_lastAngle_rad = m_plant.motorAngle_rad();
    m_angleHistory.fill(m_lastAngle_rad);
    m_integral_radPerS = 0;
    m_lpf = {};
    m_feedback_counts = resolverCount() + m_offset_counts;
}

std::int64_t Bds5Servo::resolverCount() const {
    return std::int64_t(std::floor(m_plant.motorAngle_rad() * kCountsPerRad));
}

std::int64_t Bds5Servo::feedbackAt(double angle_rad) const {
    return std::int64_t(std::floor(angle_rad * kCountsPerRad)) + m_offset_counts;
}

void Bds5Servo::normalize(std::int64_t counts) {
    m_offset_counts = counts - resolverCount();
    m_feedback_counts = counts;
}

int Bds5Servo::tick(double pcmd_counts, double profileVelocity_cps, bool enabled, Bds5VariableStore& vars) {
    const Refs& r = refs();
    // Feedback as sampled at the start of the period: the R/D count, and the 1 ms (VFB) and 16 ms (VAVG)
    // averages of the shaft speed. VFB is the R/D converter's own tracking velocity, so it is not
    // quantised to a count per ms (the BDS5 quotes 0.0005 RPM speed resolution, L544).
    const double angle = m_plant.motorAngle_rad();
    m_feedback_counts = resolverCount() + m_offset_counts;
    m_velocity_cps = (angle - m_lastAngle_rad) * kCountsPerRad / kPeriod_s;
    const double oldest = m_angleHistory[m_historyAt];
    m_angleHistory[m_historyAt] = angle;
    m_historyAt = (m_historyAt + 1) % m_angleHistory.size();
    const double vavg_cps = (angle - oldest) * kCountsPerRad / (kPeriod_s * double(m_angleHistory.size()));
    m_lastAngle_rad = angle;

    const bool pl = get(vars, r.pl) != 0;
    const bool tq = get(vars, r.tq) != 0;
    const double pe = enabled ? std::round(pcmd_counts) - double(m_feedback_counts) : 0;
    double vcmd_cps = profileVelocity_cps;
    if (pl && !tq)
        vcmd_cps = get(vars, r.kp) / ls::kKpPerInvSecond * pe + get(vars, r.kf) / ls::kUnityFeedForward * vcmd_cps;
    if (!enabled) vcmd_cps = 0;
    const double ve_cps = vcmd_cps - m_velocity_cps;

    const double ilim = std::min(get(vars, r.ilim) / kFullCurrent, 1.0);
    const double limit = std::min(ilim, m_ifold);
    const double raw = currentCommand(ve_cps * kRadPerCount, m_velocity_cps * kRadPerCount, vcmd_cps * kRadPerCount,
                                      enabled, vars, limit);
    const double icmd = std::clamp(raw, -limit, limit);
    const bool sat = enabled && std::abs(raw) >= limit;

    m_plant.step(kPeriod_s, icmd * m_plant.motor().peakCurrent_A);
    const double imon = std::abs(m_plant.current_A()) / m_plant.motor().peakCurrent_A;
    foldback(imon, get(vars, r.icont) / kFullCurrent, enabled, vars);

    put(vars, r.pfb, double(m_feedback_counts));
    put(vars, r.prd, double(((resolverCount() % 4096) + 4096) % 4096));
    put(vars, r.pe, pe);
    put(vars, r.vfb, m_velocity_cps * kBasicPerCps);
    put(vars, r.vavg, vavg_cps * kBasicPerCps);
    put(vars, r.ve, ve_cps * kBasicPerCps);
    put(vars, r.icmd, icmd * kFullCurrent);
    put(vars, r.imon, imon * kFullCurrent);
    put(vars, r.ifold, m_ifold * kFullCurrent);
    put(vars, r.sat, sat ? 1 : 0);
    put(vars, r.fold, m_ifold < ilim ? 1 : 0);

    if (std::abs(m_velocity_cps * kBasicPerCps) > get(vars, r.vospd)) return 13; // OVER-SPEED (L7195)
    if (enabled && pl && !tq && std::abs(pe) > get(vars, r.pemax)) return 25;    // PE OVERFLOW (L7230)
    return 0;
}

// The velocity loop's law for the mode (§7.17), as a fraction of IMAX before the clamp, then the LPF.
double Bds5Servo::currentCommand(double ve, double vfb, double vcmd, bool enabled, const Bds5VariableStore& vars,
                                 double limit) {
    const Refs& r = refs();
    if (!enabled) {
        m_integral_radPerS = 0;
        m_lpf = {};
        return 0;
    }
    double command = 0;
    const double kprop = get(vars, r.kprop) * ls::kKvFractionPerRadPerS;
    if (get(vars, r.tq) != 0) {
        command = kprop * vcmd; // torque mode: VFB is not subtracted
        m_integral_radPerS = 0;
    } else if (get(vars, r.prop) != 0) {
        command = kprop * ve;
        m_integral_radPerS = 0;
    } else {
        const double kv = get(vars, r.kv) * ls::kKvFractionPerRadPerS;
        const double step = ls::kviCorner_radPerS(get(vars, r.kvi)) * ve * kPeriod_s;
        const double next = kv * (m_integral_radPerS + step - vfb);
        // Anti-windup: the integrator does not run further into a saturated current.
        if (std::abs(next) < limit || (next > 0) != (step > 0)) m_integral_radPerS += step;
        command = kv * (m_integral_radPerS - vfb);
    }
    // LPF (L6475): "two cascaded, low-pass, single-pole filters, both with a 3 dB frequency of" LPFHZ. Each
    // is y += (1 - p)(x - y) with its pole p placed so the sampled filter is 3 dB down exactly at LPFHZ:
    // 2 (1 - p)^2 = |1 - p e^-jw|^2 gives p^2 - (4 - 2 cos w) p + 1 = 0 (w = 2 pi LPFHZ T). At low LPFHZ
    // p is e^-w, the continuous pole; near the 500 Hz Nyquist limit it still keeps the manual's 3 dB point.
    if (get(vars, r.lpf) != 0) {
        const double hz = std::clamp(get(vars, r.lpfhz), 1.0, 0.5 / kPeriod_s);
        if (hz != m_lpfHz) {
            m_lpfHz = hz;
            const double b = 2 - std::cos(2 * std::numbers::pi * hz * kPeriod_s);
            m_lpfAlpha = 1 - (b - std::sqrt(b * b - 1));
        }
        const double alpha = m_lpfAlpha;
        m_lpf[0] += alpha * (command - m_lpf[0]);
        m_lpf[1] += alpha * (m_lpf[0] - m_lpf[1]);
        command = m_lpf[1];
    } else {
        m_lpf = {command, command};
    }
    return command;
}

// Foldback (L2143-2168): above ICONT IFOLD falls, the faster the larger IMON is; below it recovers. The
// time constant is FOLDT/4 (sec/100): from full current IFOLD reaches IMAX after about 2.5 s and ICONT
// about 10 s (four time constants) later, as the manual says. Disabled, IFOLD is well above IMAX.
void Bds5Servo::foldback(double imon, double icont, bool enabled, const Bds5VariableStore& vars) {
    const Refs& r = refs();
    if (!enabled) {
        m_ifold = kFoldHigh;
        return;
    }
    const double fall_s = std::max(get(vars, r.foldt), 1.0) / 100 / 4;
    const double rise_s = std::max(get(vars, r.foldr), 1.0) / 100 / 4;
    if (imon > icont)
        m_ifold -= (imon - icont) / fall_s * kPeriod_s;
    else
        m_ifold += (icont - imon) / rise_s * kPeriod_s;
    m_ifold = std::clamp(m_ifold, icont, kFoldHigh);
}

} // namespace drive_core::bds5
