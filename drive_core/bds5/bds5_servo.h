// The BDS5's servo loops on the simulated motor: every 1 ms the position loop (KP, KF), the velocity loop
// (KV/KVI or KPROP, or torque mode), the two-pole LPF, the ILIM/IFOLD current clamp with foldback, then
// 1 ms of the plant; the resolver gives PFB/PRD in counts and VFB as a 1 ms average (seed-bds5 §7.17).
#pragma once

#include "bds5_variable_store.h"

#include "drive_core/physics/plant.h"

#include <array>
#include <cstdint>

namespace drive_core::bds5 {

inline constexpr double kCountsPerRev = 4096; // the reference 12-bit R/D

class Bds5Servo {
public:
    Bds5Servo();

    // The motor and load, kept across power cycles (they are hardware); the shaft starts at rest at 0.
    void setMotor(const physics::MotorParameters& motor);
    void setLoad(const physics::LoadParameters& load) { m_plant.setLoad(load); }
    const physics::Plant& plant() const { return m_plant; }
    // For TUNE's open-loop shake; call settle() after moving the shaft behind the loop's back.
    physics::Plant& plant() { return m_plant; }
    // The loop's memory (integrator, filters, velocity history) restarts from the shaft as it is now.
    void settle();
    // Power-up: the shaft where it is, the loop states cleared, PFB counted from 0.
    void powerUp();

    // One servo period (1 ms). pcmd_counts and profileVelocity_cps come from the profile generator.
    // Writes PFB, PRD, PE, VFB, VAVG, VE, ICMD, IMON, IFOLD, SAT, FOLD. Returns a fault the loop raised:
    // 13 over-speed (|VFB| > VOSPD), 25 PE overflow (|PE| > PEMAX with PL on), else 0.
    int tick(double pcmd_counts, double profileVelocity_cps, bool enabled, Bds5VariableStore& vars);

    // PFB in counts (the resolver count plus the NORM offset) and the 1 ms velocity (counts/s).
    std::int64_t feedback_counts() const { return m_feedback_counts; }
    double velocity_cps() const { return m_velocity_cps; }
    // What PFB reads (or read) with the shaft at angle_rad (position capture between two samples).
    std::int64_t feedbackAt(double angle_rad) const;
    // NORM / PFB=: PFB reads `counts` from now on, the shaft does not move.
    void normalize(std::int64_t counts);
    // Rotary roll-over: PFB reads `counts` more from now on (the shaft does not move).
    void shift(std::int64_t counts) {
        m_offset_counts += counts;
        m_feedback_counts += counts;
    }

    static constexpr double kPeriod_s = 0.001;

private:
    std::int64_t resolverCount() const;
    double currentCommand(double ve_radPerS, double vfb_radPerS, double vcmd_radPerS, bool enabled,
                          const Bds5VariableStore& vars, double limit);
    void foldback(double imon, double icont, bool enabled, const Bds5VariableStore& vars);

    physics::Plant m_plant;
    std::int64_t m_offset_counts = 0; // PFB - resolver count
    std::int64_t m_feedback_counts = 0;
    double m_lastAngle_rad = 0;
    double m_velocity_cps = 0;
    std::array<double, 16> m_angleHistory{}; // the last 16 ms, for VAVG
    std::size_t m_historyAt = 0;
    double m_integral_radPerS = 0; // the velocity loop's integrator, KVI' * integral(VE)
    std::array<double, 2> m_lpf{}; // the two cascaded poles
    double m_lpfHz = 0, m_lpfAlpha = 0;
    double m_ifold = 0; // fraction of IMAX
};

} // namespace drive_core::bds5
