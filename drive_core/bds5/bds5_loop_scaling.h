// How the BDS5's loop gains (KP, KF, KV, KVI, KPROP, plain integers) map onto physical loop gains, written
// once here and used by the servo loop and by TUNE. Chosen so that with the default reference motor the
// manual's Table 6.3 (KVI -> velocity bandwidth) and Table 6.4 (KP_max -> velocity bandwidth) hold.
#pragma once

#include <array>
#include <cstdint>
#include <numbers>
#include <utility>

namespace drive_core::bds5::loop_scaling {

// The velocity loop is the manual's pseudo-derivative-feedback structure (L3204-3206):
//   ICMD = KV' * (KVI' * integral(VE dt) - VFB)          (velocities in rad/s, ICMD as a fraction of IMAX)
// With a rigid load (J, Kt, Ipeak) its closed loop from VCMD to VFB is second order, no zero:
//   wn^2 = a * KVI',  2 zeta wn = a,  where a = Kt * Ipeak * KV' / J,
// so KVI' = wn / (2 zeta) alone sets the bandwidth for a given damping, and KV' (proportional to inertia)
// sets the damping — which is why the manual ties KVI to bandwidth (Table 6.3) and TUNE measures inertia
// to find KV. Table 6.3 is not linear in KVI (KVI per Hz falls from 280 to 200), so KVI' is the table
// itself interpolated: KVI' = kviCorner_radPerS(KVI). The corner is the one that gives the table's
// bandwidth with critical damping (stab 2: zeta = 1, -3 dB at 0.6436 wn), so wn = 2 pi BW / 0.6436 and
// KVI' = wn / 2. A fidelity test measures the discrete 1 ms loop against the table.
inline constexpr std::array<std::pair<double, double>, 8> kTable63{
    {{1400, 5}, {2650, 10}, {4000, 15}, {5000, 20}, {6250, 25}, {7500, 30}, {8750, 40}, {10000, 50}}};
inline constexpr double kCriticalBandwidthPerWn = 0.6436; // sqrt(sqrt(2) - 1): -3 dB of (wn/(s+wn))^2

// KV and KPROP: ICMD as a fraction of IMAX per rad/s of velocity, per unit of gain.
// KV 2000 on REF-MEDIUM with its matched load gives zeta near 1 at the power-up KVI 5000 (20 Hz).
inline constexpr double kKvFractionPerRadPerS = 5e-6;

// KP: the position loop's gain in 1/s is KP / kKpPerInvSecond. Chosen so Table 6.4's KP_max — the largest
// KP whose position step does not overshoot (by more than a count in 300) with KF 0 — matches: the
// cascade s(s+wn)^2 + KP' wn^2 keeps real poles up to KP' = 4/27 wn, about 1.45 BW rad/s, so KP_max =
// 100 BW wants a divisor near 69; the 1 ms loop's delay and the one-count criterion bring it to 54
// (measured within 5 % at every row by Bds5LoopFidelity.Table64KpMaxMatchesTheManual).
inline constexpr double kKpPerInvSecond = 54;

inline constexpr double kUnityFeedForward = 16384; // KF (L3178-3182)

// The corner (rad/s) of the velocity integrator for a KVI, Table 6.3 interpolated (linear beyond its
// ends, through the origin below its first row).
inline double kviCorner_radPerS(double kvi) {
    const auto corner = [](double bandwidth_Hz) {
        return 2 * std::numbers::pi * bandwidth_Hz / kCriticalBandwidthPerWn / 2;
    };
    if (kvi <= kTable63.front().first) return corner(kTable63.front().second * kvi / kTable63.front().first);
    for (std::size_t i = 1; i < kTable63.size(); ++i) {
        const auto [k0, b0] = kTable63[i - 1];
        const auto [k1, b1] = kTable63[i];
        if (kvi <= k1 || i + 1 == kTable63.size()) return corner(b0 + (b1 - b0) * (kvi - k0) / (k1 - k0));
    }
    return 0;
}

// Table 6.3 read backwards: the KVI for a velocity bandwidth (Hz).
inline double kviForBandwidth(double bandwidth_Hz) {
    if (bandwidth_Hz <= kTable63.front().second) return kTable63.front().first * bandwidth_Hz / kTable63.front().second;
    for (std::size_t i = 1; i < kTable63.size(); ++i) {
        const auto [k0, b0] = kTable63[i - 1];
        const auto [k1, b1] = kTable63[i];
        if (bandwidth_Hz <= b1 || i + 1 == kTable63.size()) return k0 + (k1 - k0) * (bandwidth_Hz - b0) / (b1 - b0);
    }
    return 0;
}

} // namespace drive_core::bds5::loop_scaling
