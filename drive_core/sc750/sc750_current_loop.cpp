// The SC750's current loop, solved exactly per servo period.
#include "sc750_current_loop.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace drive_core::sc750 {

namespace {
using Matrix6 = Eigen::Matrix<double, 6, 6>;

// exp(m) by scaling and squaring with a Taylor series; m is small (6 x 6) and well scaled, and this runs
// only when the loop's design changes.
Matrix6 exponential(const Matrix6& m) {
    const double norm = m.cwiseAbs().rowwise().sum().maxCoeff();
    const int squarings = std::max(0, int(std::ceil(std::log2(std::max(norm, 1e-300) / 0.25))));
    const Matrix6 scaled = m / std::ldexp(1.0, squarings);
    Matrix6 result = Matrix6::Identity();
    Matrix6 term = Matrix6::Identity();
    for (int k = 1; k <= 14; ++k) {
        term = term * scaled / double(k);
        result += term;
    }
    for (int i = 0; i < squarings; ++i) result = result * result;
    return result;
}
} // namespace

// States x = (i, z), z = integral of (u - i): the PI drives the winding with v = Kp (u - i + z / Ti), Kp = L wn,
// so L di/dt = -R i + v gives di/dt = -(1/tau + wn) i + (wn / Ti) z + wn u, dz/dt = u - i. With Ti = tau the
// closed loop is exactly wn / (s + wn). Back-EMF is left to the integrator (it changes slowly).
void Sc750CurrentLoop::design(double windingTau_s, double bandwidth_Hz, int ilc, double period_s) {
    m_tau_s = windingTau_s;
    m_bandwidth_Hz = bandwidth_Hz;
    m_ilc = ilc;
    m_period_s = period_s;
    const double wn = 2 * std::numbers::pi * bandwidth_Hz;
    const double ti = ilc * 1e-4;
    // Augmented [[A B 0][0 0 0][I 0]]-style block: w = (i, z, u) with u constant; the integral of exp(A t)
    // over the period (for the mean current) is the top-right block of exp([[Abar, I], [0, 0]] h).
    Matrix6 m = Matrix6::Zero();
    m(0, 0) = -(1 / windingTau_s + wn);
    m(0, 1) = wn / ti;
    m(0, 2) = wn;
    m(1, 0) = -1;
    m(1, 2) = 1;
    m.block<3, 3>(0, 3).setIdentity();
    const Matrix6 e = exponential(m * period_s);
    m_phi = e.block<2, 2>(0, 0);
    m_gamma = e.block<2, 1>(0, 2);
    m_meanX = e.block<1, 2>(0, 3) / period_s;
    m_meanU = e(0, 5) / period_s;
}

double Sc750CurrentLoop::step(double currentCommand_A) {
    const double mean = m_meanX.dot(m_x) + m_meanU * currentCommand_A;
    m_x = m_phi * m_x + m_gamma * currentCommand_A;
    return mean;
}

} // namespace drive_core::sc750
