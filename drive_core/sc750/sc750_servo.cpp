// The SC750's servo loops on the simulated plant (see sc750_servo.h; DECISIONS 47-52).
#include "sc750_servo.h"

#include "drive_core/catalog/sc750_motors.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace drive_core::sc750 {

namespace {
constexpr double kTwoPi = 2 * std::numbers::pi;
constexpr double kRadPerSPerRpm = kTwoPi / 60;
constexpr double kTransparentLoop_Hz = 1e7; // the plant's own current lag, made negligible: ours replaces it
constexpr double kCurrentLoop_Hz = 1000;    // chosen: the current loop with ILC on the winding's pole
constexpr double kTorqueBlock_APerV = 2.0;  // BLKTYPE 0 with KVP = 1, KVI = 0 (L1945-L1952)
constexpr double kVelocityBlock_RpmPerV = 1000; // BLKTYPE 1: 1 kRPM/V (L1946)

// The reference motors' winding time constants (they carry none): chosen, growing with the frame.
double referenceWindingTau_s(std::string_view name) {
    if (name == "REF-SMALL") return 1.0e-3;
    if (name == "REF-LARGE") return 4.0e-3;
    return 2.0e-3;
}
} // namespace

bool findSc750Motor(std::string_view name, Sc750Motor* out) {
    if (const catalog::sc750::MotorInfo* m = catalog::sc750::findMotor(name)) {
        const catalog::sc750::SetupData& d = m->data;
        physics::MotorParameters p;
        p.torqueConstant_NmPerA = d.torqueConstant_NmPerA;
        p.rotorInertia_kgm2 = d.rotorInertia_kgcm2 * 1e-4;
        p.coulombFriction_Nm = 0.005 * d.torqueConstant_NmPerA * d.peak_A; // chosen: 0.5 % of peak torque
        p.viscousFriction_NmPerRadPerS = p.coulombFriction_Nm / 500;       // as much again near 4800 RPM
        p.continuousCurrent_A = d.continuous_A;
        p.peakCurrent_A = d.peak_A;
        p.maxSpeed_rpm = d.maxSpeed_rpm;
        p.currentLoopBandwidth_Hz = kCurrentLoop_Hz;
        *out = Sc750Motor{std::string(m->part), p, d.inductance_mH / d.resistance_ohm * 1e-3};
        return true;
    }
    if (const physics::ReferenceMotor* r = physics::findReferenceMotor(name)) {
        *out = Sc750Motor{std::string(r->name), r->motor, referenceWindingTau_s(r->name)};
        return true;
    }
    return false;
}

Sc750Motor defaultSc750Motor() {
    Sc750Motor motor;
    findSc750Motor("R32G", &motor);
    return motor;
}

namespace {
physics::MotorParameters plantMotor(const Sc750Motor& m) {
    physics::MotorParameters p = m.motor;
    p.currentLoopBandwidth_Hz = kTransparentLoop_Hz;
    return p;
}
physics::LoadParameters noLoad() {
    physics::LoadParameters load;
    load.inertia_kgm2 = 0; // Auto set-up assumes no load (DECISIONS 46); the bench adds one
    return load;
}
} // namespace

Sc750Servo::Sc750Servo() : m_motor(defaultSc750Motor()), m_plant(plantMotor(m_motor), noLoad()) {
    powerUp();
}

void Sc750Servo::setMotor(const Sc750Motor& motor) {
    m_motor = motor;
    m_plant = physics::Plant(plantMotor(motor), m_plant.load());
    powerUp();
}

void Sc750Servo::powerUp() {
    m_origin_rad = m_lastAngle_rad = m_plant.motorAngle_rad();
    m_angleHistory.fill(m_lastAngle_rad);
    m_velocity_radPerS = m_vcmd_radPerS = m_verr_radPerS = 0;
    m_arf = {};
    m_integral_radPerS = m_icmd_A = m_it_A = 0;
    m_cwRamp_radPerS = m_ccwRamp_radPerS = -1;
    m_currentLoop.reset();
}

double Sc750Servo::averageVelocity_cps() const {
    const double oldest = m_angleHistory[m_historyAt]; // the next slot to be written is the oldest
    return (m_lastAngle_rad - oldest) / (kPeriod_s * double(m_angleHistory.size() - 1)) * kCountsPerRad;
}

// y += alpha (x - y) is the exact first-order low-pass at hz for an input held over the tick.
double Sc750Servo::filterAlpha(double hz, std::size_t which) {
    if (hz != m_alphaHz[which]) {
        m_alphaHz[which] = hz;
        m_alpha[which] = 1 - std::exp(-kTwoPi * std::max(hz, 0.0) * kPeriod_s);
    }
    return m_alpha[which];
}

void Sc750Servo::tick(const ServoCommand& command, const ServoSettings& s) {
    // Feedback as sampled at the start of the period: the angle and the speed over the last period.
    const double angle = m_plant.motorAngle_rad();
    m_velocity_radPerS = (angle - m_lastAngle_rad) / kPeriod_s;
    m_lastAngle_rad = angle;
    m_angleHistory[m_historyAt] = angle;
    m_historyAt = (m_historyAt + 1) % m_angleHistory.size();

    double current = 0;
    if (!command.enabled) { // the power stage is off: no current, the motor coasts; the loops restart from rest
        m_vcmd_radPerS = m_verr_radPerS = m_integral_radPerS = m_icmd_A = 0;
        m_arf = {};
        m_cwRamp_radPerS = m_ccwRamp_radPerS = -1;
        m_currentLoop.reset();
    } else {
        const double v = m_velocity_radPerS;
        // The velocity loop's command for the block (L1930-L1948).
        double vcmd = 0;
        if (s.blocktype == 1) {
            vcmd = s.cmdgain * kVelocityBlock_RpmPerV * command.analog_V * kRadPerSPerRpm;
        } else if (s.blocktype != 0) {
            const double error_rad = (command.position_counts - position_counts()) / kCountsPerRad;
            vcmd = kTwoPi * s.kpp_Hz * error_rad + s.kvff_percent / 100 * command.velocity_cps / kCountsPerRad;
        }
        // An active inhibit brings the shaft to rest at DECEL.RATE and then asks for no speed its way (L1484):
        // the loop makes no torque to move that way, yet may still brake motion that way and resist a load.
        const double brake = command.inhibitDecel_cps2 / kCountsPerRad * kPeriod_s;
        if (command.inhibitCw) {
            m_cwRamp_radPerS = m_cwRamp_radPerS < 0 ? std::max(0.0, v) : std::max(0.0, m_cwRamp_radPerS - brake);
            vcmd = std::min(vcmd, m_cwRamp_radPerS);
        } else {
            m_cwRamp_radPerS = -1;
        }
        if (command.inhibitCcw) {
            m_ccwRamp_radPerS = m_ccwRamp_radPerS < 0 ? std::max(0.0, -v) : std::max(0.0, m_ccwRamp_radPerS - brake);
            vcmd = std::max(vcmd, -m_ccwRamp_radPerS);
        } else {
            m_ccwRamp_radPerS = -1;
        }
        m_vcmd_radPerS = s.blocktype == 0 ? 0 : vcmd;
        m_verr_radPerS = s.blocktype == 0 ? 0 : vcmd - v;
        // The torque block feeds the scaled analog command through the compensator without feedback: with
        // KVP = 1 and KVI = 0 that is 2 A/V x CMDGAIN (L1945-L1952).
        const double input = s.blocktype == 0 ? kTorqueBlock_APerV * s.cmdgain * command.analog_V : m_verr_radPerS;
        // Anti-resonant filters: two first-order low-passes on the velocity error (FVEL.ERR, L2152).
        m_arf[0] += filterAlpha(s.arf0_Hz, 0) * (input - m_arf[0]);
        m_arf[1] += filterAlpha(s.arf1_Hz, 1) * (m_arf[0] - m_arf[1]);
        // Velocity PI: ICMD = KVP (FVEL.ERR + 2 pi KVI integral(FVEL.ERR)), clamped by ILMT.PLUS (CW) and
        // ILMT.MINUS (CCW); the integral does not run further into the clamp.
        const double upper = s.ilmtPlus_percent / 100 * s.controllerPeak_A;
        const double lower = -s.ilmtMinus_percent / 100 * s.controllerPeak_A;
        const double step = kTwoPi * s.kvi_Hz * m_arf[1] * kPeriod_s;
        const double next = s.kvp_APerRadPerS * (m_arf[1] + m_integral_radPerS + step);
        if ((next < upper || step < 0) && (next > lower || step > 0)) m_integral_radPerS += step;
        if (s.kvi_Hz == 0) m_integral_radPerS = 0;
        m_icmd_A = std::clamp(s.kvp_APerRadPerS * (m_arf[1] + m_integral_radPerS), lower, upper);
        m_currentLoop.configure(m_motor.windingTau_s, m_motor.motor.currentLoopBandwidth_Hz, s.ilc, kPeriod_s);
        current = m_currentLoop.step(m_icmd_A);
    }
    m_plant.step(kPeriod_s, current);
    // I.t: |IFB| low-passed at ITF0 (IT.FILT, L2161).
    m_it_A += filterAlpha(s.itf0_Hz, 2) * (std::abs(m_plant.current_A()) - m_it_A);
}

} // namespace drive_core::sc750
