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
    m_plan.dt_s = -1;
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

void Plant::plan(double dt_s) {
    Plan& p = m_plan;
    p.dt_s = dt_s;
    // The sub-step: a rigid shaft's own dynamics (friction sticking at 1/kStickTime_s) are slow enough for
    // kSubStep_s; a compliant coupling needs a fraction of its resonance period.
    double maxStep = kSubStep_s;
    if (!rigid()) maxStep = std::min(maxStep, 0.05 / std::max(resonance_Hz(), 1.0));
    p.steps = std::max(1, int(std::ceil(dt_s / maxStep - 1e-9)));
    p.h = dt_s / p.steps;
    const double tau = 1.0 / (2 * std::numbers::pi * m_motor.currentLoopBandwidth_Hz);
    p.decay = std::exp(-p.h / tau);
    p.meanFactor = tau / p.h * (1 - p.decay);
    const double j = m_motor.rotorInertia_kgm2 + m_load.inertia_kgm2;
    const double beta = (m_motor.viscousFriction_NmPerRadPerS + m_load.viscousFriction_NmPerRadPerS) / j;
    const double x = beta * p.h;
    p.e = std::exp(-x);
    if (x < 1e-3) { // the series: (1 - e) / beta and (h - phi1) / beta lose digits to cancellation here
        p.phi1 = p.h * (1 - x / 2 * (1 - x / 3 * (1 - x / 4)));
        p.phi2 = p.h * p.h * (0.5 - x / 6 * (1 - x / 4 * (1 - x / 5)));
    } else {
        p.phi1 = -std::expm1(-x) / beta;
        p.phi2 = (p.h - p.phi1) / beta;
    }
    p.torquePerA = m_motor.torqueConstant_NmPerA / j;
    p.load = m_load.externalTorque_Nm / j;
    p.friction = m_motor.coulombFriction_Nm / j;
}

void Plant::step(double dt_s, double currentCommand_A) {
    if (dt_s != m_plan.dt_s) plan(dt_s);
    const Plan& p = m_plan;
    const double command = std::clamp(currentCommand_A, -m_motor.peakCurrent_A, m_motor.peakCurrent_A);
    // The current loop is first order and exact over the sub-step; the mechanics take the current's exact
    // mean over the sub-step, solved exactly for a rigid shaft turning one way, else by RK4.
    const bool oneMass = rigid();
    for (int i = 0; i < p.steps; ++i) {
        const double next = command + (m_current_A - command) * p.decay;
        const double mean = command + (m_current_A - command) * p.meanFactor;
        if (!oneMass || !stepRigidExactly(mean)) stepRk4(p.h, mean);
        m_current_A = next;
    }
}

void Plant::stepRk4(double h, double current_A) {
    const State k1 = derivative(m_x, current_A);
    if ((k1.array() == 0.0).all()) return; // at rest and held there (friction): every slope is 0, m_x stays
    const State k2 = derivative(m_x + 0.5 * h * k1, current_A);
    const State k3 = derivative(m_x + 0.5 * h * k2, current_A);
    const State k4 = derivative(m_x + h * k3, current_A);
    m_x += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
}

// A rigid shaft turning one way the whole sub-step obeys w' = a - beta w with a constant (torque, load and
// Coulomb friction over J) and beta = b / J: solved exactly, a tenth of RK4's work (the simulators' speed,
// issue 18). Not when the speed starts or ends inside the sticking band or changes sign: friction is not
// linear there, so RK4 takes the sub-step. False then, with the state untouched.
bool Plant::stepRigidExactly(double current_A) {
    const Plan& p = m_plan;
    const double w0 = m_x(1);
    if (std::abs(w0) < kStickSpeed_radPerS) return false;
    const double direction = w0 > 0 ? 1.0 : -1.0;
    const double a = p.torquePerA * current_A - p.load - p.friction * direction;
    const double w1 = p.e * w0 + p.phi1 * a;
    if (w1 * direction < kStickSpeed_radPerS) return false; // slowed into the band or reversed
    const double turn = p.phi1 * w0 + p.phi2 * a;
    m_x(0) += turn;
    m_x(2) += turn;
    m_x(3) += w1 - w0;
    m_x(1) = w1;
    return true;
}

} // namespace drive_core::physics
