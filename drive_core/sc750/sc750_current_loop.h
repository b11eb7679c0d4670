// The SC750's analog current loop (ILC, DECISIONS 48): a PI compensator whose zero sits at ILC × 0.1 ms,
// closing on the motor winding's L/R pole. With ILC on the winding's pole the loop is first order at the
// drive's current-loop bandwidth; off it, a slow tail (ILC too high) or an overshoot (too low) appears.
// Solved exactly over each servo period with the command held (a precomputed matrix exponential).
#pragma once

#include <Eigen/Dense>

namespace drive_core::sc750 {

class Sc750CurrentLoop {
public:
    // The loop's design: the winding's time constant L/R (s), the bandwidth with a matched zero (Hz), the
    // compensator's zero ILC (0.1 ms units, >= 1) and the period the command is held (s). Recomputes the
    // transition matrices only when one of them changed.
    void configure(double windingTau_s, double bandwidth_Hz, int ilc, double period_s) {
        ilc = ilc < 1 ? 1 : ilc;
        if (windingTau_s != m_tau_s || bandwidth_Hz != m_bandwidth_Hz || ilc != m_ilc || period_s != m_period_s)
            design(windingTau_s, bandwidth_Hz, ilc, period_s); // the loop asks every tick: mostly nothing changed
    }
    // One period with currentCommand_A held; returns the mean current over it (A).
    double step(double currentCommand_A);
    double current_A() const { return m_x(0); }
    void reset() { m_x.setZero(); }

private:
    void design(double windingTau_s, double bandwidth_Hz, int ilc, double period_s);

    Eigen::Vector2d m_x = Eigen::Vector2d::Zero(); // current (A), the PI's integral of the error (A s)
    Eigen::Matrix2d m_phi = Eigen::Matrix2d::Identity();
    Eigen::Vector2d m_gamma = Eigen::Vector2d::Zero();
    Eigen::RowVector2d m_meanX = Eigen::RowVector2d::Zero(); // mean current = m_meanX x0 + m_meanU u
    double m_meanU = 0;
    double m_tau_s = -1, m_bandwidth_Hz = -1, m_period_s = -1;
    int m_ilc = -1;
};

} // namespace drive_core::sc750
