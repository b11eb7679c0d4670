// Motor and load dynamics.
#include "plant.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace drive_core::physics {

namespace {
constexpr double kSubStep_s = 1e-3;          // RK4 sub-step for a rigid shaft (the current loop is exact)
constexpr double kStickSpeed_radPerS = 1e-3; // Karnopp friction: below this speed the shaft may stick
constexpr double kStickTime_s = 5e-4;        // a sticking shaft's leftover speed decays this fast

// Coulomb friction after Karnopp: moving, it opposes the motion; (nearly) at rest it holds as long as the
// other torques do not exceed it. Returns the acceleration the friction leaves.
double withFriction(double speed, double otherTorque, double friction, double inertia) {
    if (std::abs(speed) < kStickSpeed_radPerS && std::abs(otherTorque) <= friction) return -speed / kStickTime_s;
    const double direction =
        std::abs(speed) >= kStickSpeed_radPerS ? (speed > 0 ? 1.0 : -1.0) : (otherTorque > 0 ? 1.0 : -1.0);
    return (otherTorque - friction * direction) / inertia;
}
} // namespace

Plant::Plant(MotorParameters motor, LoadParameters load) : m_motor(motor), m_load(load) {}

void Plant::setLoad(const LoadParameters& load) {
    const bool wasRigid = rigid();
    m_load = load;
    if (wasRigid && !rigid()) { // the load starts where the motor is
        m_x(2) = m_x(0);
        m_x(3) = m_x(1);
    }
}

void Plant::setAngle(double angle_rad) {
    m_x(0) = angle_rad;
    m_x(2) = angle_rad;
}

double Plant::resonance_Hz() const {
    if (rigid()) return 0;
    const double jm = m_motor.rotorInertia_kgm2;
    const double jl = std::max(m_load.inertia_kgm2, 1e-12);
    return std::sqrt(m_load.couplingStiffness_NmPerRad * (jm + jl) / (jm * jl)) / (2 * std::numbers::pi);
}

Plant::State Plant::derivative(const State& x, double current_A) const {
    const double torque = m_motor.torqueConstant_NmPerA * current_A;
    State dx;
    if (rigid()) { // one mass: motor and load turn together
        const double j = m_motor.rotorInertia_kgm2 + m_load.inertia_kgm2;
        const double b = m_motor.viscousFriction_NmPerRadPerS + m_load.viscousFriction_NmPerRadPerS;
        const double acc =
            withFriction(x(1), torque - b * x(1) - m_load.externalTorque_Nm, m_motor.coulombFriction_Nm, j);
        dx << x(1), acc, x(1), acc;
        return dx;
    }
    const double twist = x(0) - x(2);
    const double twistRate = x(1) - x(3);
    const double spring = m_load.couplingStiffness_NmPerRad * twist + m_load.couplingDamping_NmPerRadPerS * twistRate;
    const double motorAcc = withFriction(x(1), torque - m_motor.viscousFriction_NmPerRadPerS * x(1) - spring,
                                         m_motor.coulombFriction_Nm, m_motor.rotorInertia_kgm2);
    const double loadAcc = (spring - m_load.viscousFriction_NmPerRadPerS * x(3) - m_load.externalTorque_Nm) /
                           std::max(m_load.inertia_kgm2, 1e-12);
    dx << x(1), motorAcc, x(3), loadAcc;
    return dx;
}

void Plant::step(double dt_s, double currentCommand_A) {
    const double command = std::clamp(currentCommand_A, -m_motor.peakCurrent_A, m_motor.peakCurrent_A);
    const double tau = 1.0 / (2 * std::numbers::pi * m_motor.currentLoopBandwidth_Hz);
    // The sub-step: a rigid shaft's own dynamics (friction sticking at 1/kStickTime_s) are slow enough for
    // kSubStep_s; a compliant coupling needs a fraction of its resonance period.
    double maxStep = kSubStep_s;
    if (!rigid()) maxStep = std::min(maxStep, 0.05 / std::max(resonance_Hz(), 1.0));
    const int steps = std::max(1, int(std::ceil(dt_s / maxStep - 1e-9)));
    const double h = dt_s / steps;
    if (h != m_decayStep_s || tau != m_decayTau_s) { // the same every servo period: computed once
        m_decayStep_s = h;
        m_decayTau_s = tau;
        m_decay = std::exp(-h / tau);
    }
    const double decay = m_decay;
    // The current loop is first order and exact over the sub-step; the mechanics go by RK4 with the
    // current's exact mean over the sub-step.
    const double meanFactor = tau / h * (1 - decay);
    for (int i = 0; i < steps; ++i) {
        const double next = command + (m_current_A - command) * decay;
        const double mean = command + (m_current_A - command) * meanFactor;
        const State k1 = derivative(m_x, mean);
        if ((k1.array() == 0.0).all()) { // at rest and held there (friction): every slope is 0, m_x stays
            m_current_A = next;
            continue;
        }
        const State k2 = derivative(m_x + 0.5 * h * k1, mean);
        const State k3 = derivative(m_x + 0.5 * h * k2, mean);
        const State k4 = derivative(m_x + h * k3, mean);
        m_x += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
        m_current_A = next;
    }
}

} // namespace drive_core::physics
