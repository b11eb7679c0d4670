// The PMC-960's analog loops on the plant. Numbers S1-S12 refer to DECISIONS.md ("Servo physics").
#include "pmc960_servo.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace drive_core::pmc960 {

namespace {
constexpr double kRail_V = 10;                    // op-amp outputs and ICMD span +-10 V (S8)
constexpr double kPoserrPerCount_V = 10.0 / 2048; // the PSJ's 12-bit bipolar D/A (L206; S5)
constexpr double kPsjMin = -2048, kPsjMax = 2047; // the D/A saturates beyond its 12 bits (S5)
constexpr double kPositionGainPerStep = 0.04;     // PLGAIN: V/V per step, linear 1-255 = 48 dB (S2)
constexpr double kVelocityGainPerStep = 0.75;     // VLGAIN: V/V per step, linear 1-255 = 48 dB (S2)
constexpr double kTachFactory = 160;              // TGAIN 160: 10 V at the motor's top speed (S3)
constexpr double kFeedForwardUnit = 100;          // FFGAIN g multiplies the reference D/A by g/100 (S4)
constexpr double kLockUnity = 8;                  // ALGAIN 8: the inter-LSB signal is one count per count (S7)
constexpr double kBrakeResistance_Ohm = 1;        // the disabled servodrive's dynamic brake (S9)
constexpr double kTachFilter_Hz = 300;            // the RC on the tach input against commutator ripple (S10)
constexpr double kTwoPi = 2 * std::numbers::pi;
} // namespace

Pmc960Servo::Pmc960Servo()
    : m_plant(physics::MotorParameters{}, physics::LoadParameters{}),
      m_tachAlpha(1 - std::exp(-kTwoPi * kTachFilter_Hz * kPeriod_s)) {
    setGains(Gains{});
}

void Pmc960Servo::setGains(const Gains& gains) {
    m_gains = gains;
    m_gains.countsPerRev = std::max(1.0, gains.countsPerRev);
    m_gains.rangeTop_cps = std::max(1.0, gains.rangeTop_cps);
    const physics::MotorParameters& motor = m_plant.motor();
    const double topSpeed_radPerS = std::max(1.0, motor.maxSpeed_rpm * kTwoPi / 60);
    m_gp = kPositionGainPerStep * gains.positionGain;
    m_gv = kVelocityGainPerStep * gains.velocityGain;
    m_we = kTwoPi * gains.positionComp / 67.0; // L629 prints VLCOMP/67: PLCOMP meant (digest §2.5)
    m_wb = kTwoPi * gains.velocityComp / 20.0; // L603
    m_tach_VperRadS = kRail_V * (gains.tachGain / kTachFactory) / topSpeed_radPerS;
    m_ff_VperCps = kRail_V / m_gains.rangeTop_cps * gains.feedForwardGain / kFeedForwardUnit;
    m_lock = gains.lockGain / kLockUnity;
}

void Pmc960Servo::setMotor(const physics::MotorParameters& motor) {
    const std::int64_t here = count();
    m_plant = physics::Plant(motor, m_plant.load());
    setGains(m_gains); // the tach scale follows the motor's top speed
    setCount(here);
    resetIntegrators();
}

double Pmc960Servo::countsPerRad() const {
    return m_gains.countsPerRev / kTwoPi;
}

std::int64_t Pmc960Servo::count() const {
    return std::int64_t(std::floor(m_plant.motorAngle_rad() * countsPerRad() + 0.5)) + m_offset_counts;
}

double Pmc960Servo::position_counts() const {
    return m_plant.motorAngle_rad() * countsPerRad() + double(m_offset_counts);
}

double Pmc960Servo::velocity_cps() const {
    return m_plant.motorSpeed_radPerS() * countsPerRad();
}

void Pmc960Servo::setCount(std::int64_t counts) {
    m_offset_counts = counts - std::int64_t(std::floor(m_plant.motorAngle_rad() * countsPerRad() + 0.5));
}

void Pmc960Servo::stallAt(double counts) {
    const std::int64_t offset = m_offset_counts;
    const double angle = (counts - double(offset)) / countsPerRad();
    m_plant = physics::Plant(m_plant.motor(), m_plant.load()); // at rest, no current
    m_plant.setAngle(angle);
    m_offset_counts = offset;
}

void Pmc960Servo::resetIntegrators() {
    m_positionIntegral_Vs = 0;
    m_velocityIntegral_Vs = 0;
}

void Pmc960Servo::tick(Loop loop, double psj_counts, double referenceVelocity_cps, double torqueFraction) {
    const physics::MotorParameters& motor = m_plant.motor();
    const double speed = m_plant.motorSpeed_radPerS();
    m_tach_V += m_tachAlpha * (m_tach_VperRadS * speed - m_tach_V); // the filter runs in every mode
    double current_A = 0;
    double velocityCommand_V = 0; // the summing junction's command: feedforward plus position compensation
    switch (loop) {
    case Loop::Off: // S9: the armature shorted through the brake resistor
        resetIntegrators();
        m_icmd_V = 0;
        current_A = -speed * motor.torqueConstant_NmPerA / kBrakeResistance_Ohm;
        break;
    case Loop::Torque: // FPS (L1676-1680): both compensators disabled, ST torque applied
        resetIntegrators();
        m_icmd_V = std::clamp(torqueFraction, -1.0, 1.0) * kRail_V;
        current_A = m_icmd_V / kRail_V * motor.peakCurrent_A;
        break;
    case Loop::Velocity:
    case Loop::Position: {
        const double tach = m_tach_V;
        const double feedForward = std::clamp(m_ff_VperCps * referenceVelocity_cps, -kRail_V, kRail_V);
        double positionCommand = 0;
        if (loop == Loop::Position) {
            // POSERR: the D/A's count, plus the inter-LSB analog (ALOCK) where the R/D's word ends (S7).
            const double shaft = m_plant.motorAngle_rad() * countsPerRad();
            const double interLsb = shaft - std::floor(shaft + 0.5); // -0.5 .. 0.5 count
            const double poserr = (std::clamp(psj_counts, kPsjMin, kPsjMax) - m_lock * interLsb) * kPoserrPerCount_V;
            const double next = m_positionIntegral_Vs + poserr * kPeriod_s;
            positionCommand = m_gp * (poserr + m_we * next);
            // The integrator stops at the rail (the amplifier saturates, S8).
            if (std::abs(positionCommand) < kRail_V || (poserr > 0) != (m_positionIntegral_Vs > 0))
                m_positionIntegral_Vs = next;
            positionCommand = std::clamp(positionCommand, -kRail_V, kRail_V);
        } else {
            m_positionIntegral_Vs = 0;
        }
        velocityCommand_V = feedForward + positionCommand;
        const double sum = velocityCommand_V - tach;
        const double next = m_velocityIntegral_Vs + sum * kPeriod_s;
        const double icmd = m_gv * (sum + m_wb * next);
        if (std::abs(icmd) < kRail_V || (sum > 0) != (m_velocityIntegral_Vs > 0)) m_velocityIntegral_Vs = next;
        m_icmd_V = std::clamp(icmd, -kRail_V, kRail_V);
        current_A = m_icmd_V / kRail_V * motor.peakCurrent_A; // S8: 10 V = the servodrive's peak current
        break;
    }
    }
    m_tachScope.push(m_tach_V, velocityCommand_V, double(++m_periods) * kPeriod_s);
    m_plant.step(kPeriod_s, current_A);
}

double Pmc960Servo::positionLoopGain_perS() const {
    // The velocity loop turns POSERR volts into speed at 1/tach: kv = Gp (V/count) / (tach V per count/s).
    const double tachPerCps = m_tach_VperRadS / countsPerRad();
    return tachPerCps > 0 ? m_gp * kPoserrPerCount_V / tachPerCps : 0;
}

double Pmc960Servo::feedForwardShare() const {
    const double tachPerCps = m_tach_VperRadS / countsPerRad();
    return tachPerCps > 0 ? m_ff_VperCps / tachPerCps : 0;
}

} // namespace drive_core::pmc960
