// The simulated BDS5's loops against the manual's tuning tables: Table 6.3 (KVI -> velocity-loop
// bandwidth, measured by a sine sweep) and Table 6.4 (KP_max -> velocity-loop bandwidth, the largest KP
// whose position step does not overshoot), with the default reference motor, each within ±15 %.
#include "bds5_loop_probe.h"

#include "drive_core/bds5/bds5_loop_scaling.h"
#include "drive_core/bds5/bds5_tune.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace bds5_test;
using drive_core::bds5::Bds5Servo;
using drive_core::bds5::Bds5Tune;
namespace ls = drive_core::bds5::loop_scaling;

namespace {
// KV as TUNE sets it for critical damping at the row's bandwidth on the default load.
double criticalKv(double bandwidth_Hz) {
    const Bds5Servo servo;
    return Bds5Tune::gainsFor(bandwidth_Hz, 1.0, defaultInertia_kgm2(), servo.plant().motor().torqueConstant_NmPerA,
                              servo.plant().motor().peakCurrent_A)
        .kv;
}
} // namespace

TEST(Bds5LoopFidelity, Table63VelocityBandwidthMatchesTheManual) {
    std::printf("Table 6.3  KVI -> velocity-loop bandwidth (sine sweep, -3 dB, KV for critical damping)\n");
    for (const auto& [kvi, manual_Hz] : ls::kTable63) {
        const double measured = velocityBandwidth_Hz({criticalKv(manual_Hz), kvi, 0});
        std::printf("  KVI %6.0f  manual %4.0f Hz  simulated %6.1f Hz  (%+5.1f %%)\n", kvi, manual_Hz, measured,
                    (measured / manual_Hz - 1) * 100);
        EXPECT_NEAR(measured, manual_Hz, 0.15 * manual_Hz) << "KVI " << kvi;
    }
}

TEST(Bds5LoopFidelity, Table64KpMaxMatchesTheManual) {
    std::printf("Table 6.4  KP_max (no overshoot > 1 count in a 300-count step, KF 0) per velocity bandwidth\n");
    for (const auto& [kvi, bandwidth_Hz] : ls::kTable63) {
        const double manual = 100 * bandwidth_Hz; // Table 6.4: 500 at 5 Hz ... 5000 at 50 Hz
        LoopGains g{criticalKv(bandwidth_Hz), kvi, manual / 4};
        while (g.kp < 32767 && positionOvershoot({g.kv, g.kvi, g.kp * 1.01}, 300) <= 0.005) g.kp *= 1.01;
        std::printf("  %4.0f Hz  manual KP_max %5.0f  simulated %6.0f  (%+5.1f %%)\n", bandwidth_Hz, manual, g.kp,
                    (g.kp / manual - 1) * 100);
        EXPECT_NEAR(g.kp, manual, 0.15 * manual) << bandwidth_Hz << " Hz";
    }
}

TEST(Bds5LoopFidelity, DefaultGainsAreStableAndNearTwentyHertz) { // power-up KV 2000, KVI 5000
    const double measured = velocityBandwidth_Hz({2000, 5000, 0});
    EXPECT_NEAR(measured, 20, 4);
}
