// The motor and its load as an Eigen state-space model: motor and load angle and speed, coupled by a
// spring and damper (two masses, so a compliant coupling shows its resonance) or rigidly (one mass), with
// viscous and Coulomb friction and an external load torque; driven by the current from a first-order
// (analog) current loop. Stepped in fixed time by sub-steps (exact where the motion is linear, else RK4);
// never reads a clock.
#pragma once

#include "motor_parameters.h"

#include <Eigen/Dense>

namespace drive_core::physics {

class Plant {
public:
    Plant(MotorParameters motor, LoadParameters load);

    // Advances dt_s with the current command held (A, clamped to the peak current).
    void step(double dt_s, double currentCommand_A);

    double motorAngle_rad() const { return m_x(0); }
    double motorSpeed_radPerS() const { return m_x(1); }
    double loadAngle_rad() const { return m_x(2); }
    double loadSpeed_radPerS() const { return m_x(3); }
    double current_A() const { return m_current_A; }
    double motorTorque_Nm() const { return m_motor.torqueConstant_NmPerA * m_current_A; }

    void setLoad(const LoadParameters& load);
    const MotorParameters& motor() const { return m_motor; }
    const LoadParameters& load() const { return m_load; }
    // The coupling's resonance (Hz), 0 when rigid.
    double resonance_Hz() const;
    // Moves both shafts without motion (NORM-like set-up, tests).
    void setAngle(double angle_rad);

private:
    using State = Eigen::Vector4d;
    State derivative(const State& x, double current_A) const;
    void plan(double dt_s);
    void stepRk4(double h, double current_A);
    bool stepRigidExactly(double current_A);
    bool rigid() const { return m_load.couplingStiffness_NmPerRad <= 0; }

    MotorParameters m_motor;
    LoadParameters m_load;
    State m_x = State::Zero();
    double m_current_A = 0;
    // What a step of Plan::dt_s takes, worked out once (a servo period is the same every time; a new load
    // asks again): its sub-steps, the current loop's decay and mean over one, and for a rigid shaft the
    // exact solution's coefficients (see stepRigidExactly).
    struct Plan {
        double dt_s = -1;
        int steps = 1;
        double h = 0, decay = 0, meanFactor = 0;
        double e = 0, phi1 = 0, phi2 = 0;                 // exp(-beta h), (1 - e) / beta, (h - phi1) / beta
        double torquePerA = 0, load = 0, friction = 0;    // Kt / J, load torque / J, Coulomb friction / J
    } m_plan;
};

} // namespace drive_core::physics
