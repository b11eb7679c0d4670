// S-curves (SCRV 1-5, Table 3.7, L2286-2312) with fixed seeds: random moves with every SCRV land exactly
// on their count and never exceed their speed or VMAX; ACC/DEC are the *average* rates, so segment times
// follow the straight-line formulas while the peak acceleration rises with the shape.
#include "drive_core/bds5/bds5_motion.h"
#include "drive_core/motion/s_curve.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using drive_core::bds5::Bds5Motion;
using drive_core::bds5::Bds5VariableStore;
using drive_core::motion::SCurve;
using drive_core::motion::sCurvePeak;
using namespace std::chrono_literals;

namespace {
constexpr double kBasicPerCps = 65.536;    // velocity: 1/65536 count per ms
constexpr double kBasicPerCps2 = 0.065536; // acceleration: 1/65536 count per ms²
constexpr double kVmaxBasic = 33554250;    // 7500 RPM, the power-up VMAX
constexpr double kSlack = 1 + 1e-9;

Bds5VariableStore freshStore(int scrv) {
    Bds5VariableStore vars;
    vars.set("PLIM", 0);
    vars.set("SCRV", scrv);
    return vars;
}

// The SEG number every millisecond until motion stops.
std::vector<int> segmentsPerMs(Bds5Motion& motion, Bds5VariableStore& vars, int maxMs) {
    std::vector<int> seg;
    for (int ms = 0; ms < maxMs && motion.moving(); ++ms) {
        motion.step(1ms, vars);
        seg.push_back(vars.read("SEG").value_or(-1));
    }
    return seg;
}
} // namespace

TEST(Bds5SCurveProperty, ShapesAreAveragesWithTheDocumentedPeaks) {
    for (int level = 1; level <= 5; ++level) {
        const SCurve s = drive_core::motion::sCurveFromLevel(level);
        // ∫g = 1 (G(1) = 1), distance A·T²/2 (H(1) = 1/2), and G' = g, H' = G numerically.
        EXPECT_DOUBLE_EQ(drive_core::motion::sCurveVelocity(s, 1), 1) << "SCRV " << level;
        EXPECT_DOUBLE_EQ(drive_core::motion::sCurvePosition(s, 1), 0.5) << "SCRV " << level;
        for (double tau = 0.01; tau < 1; tau += 0.01) {
            const double h = 1e-6;
            const double dG =
                (drive_core::motion::sCurveVelocity(s, tau + h) - drive_core::motion::sCurveVelocity(s, tau - h)) /
                (2 * h);
            const double dH =
                (drive_core::motion::sCurvePosition(s, tau + h) - drive_core::motion::sCurvePosition(s, tau - h)) /
                (2 * h);
            EXPECT_NEAR(dG, drive_core::motion::sCurveAcceleration(s, tau), 1e-5) << level << " at " << tau;
            EXPECT_NEAR(dH, drive_core::motion::sCurveVelocity(s, tau), 1e-5) << level << " at " << tau;
        }
    }
    EXPECT_DOUBLE_EQ(sCurvePeak(SCurve::Straight), 1);
    EXPECT_NEAR(sCurvePeak(SCurve::ModifiedPolynomial), 4.0 / 3, 1e-12);
    EXPECT_NEAR(sCurvePeak(SCurve::Polynomial), 1.5, 1e-12);
    EXPECT_NEAR(sCurvePeak(SCurve::ModifiedSinusoid), 1.5, 1e-12);
    EXPECT_NEAR(sCurvePeak(SCurve::Sinusoid), M_PI / 2, 1e-12);
    // S-curves start gently: no jump in acceleration at the ends (except the straight line).
    for (int level = 2; level <= 5; ++level)
        EXPECT_NEAR(drive_core::motion::sCurveAcceleration(drive_core::motion::sCurveFromLevel(level), 0), 0, 1e-12);
}

TEST(Bds5SCurveProperty, RandomMovesWithEveryScrvLandOnTheirCountWithinVmax) {
    std::mt19937 random(4'2026'5);
    std::uniform_real_distribution<double> unit(0, 1);
    int violations = 0;
    int moves = 0;
    for (int level = 1; level <= 5; ++level) {
        Bds5VariableStore vars = freshStore(level);
        Bds5Motion motion;
        const double peak = sCurvePeak(drive_core::motion::sCurveFromLevel(level));
        for (int i = 0; i < 400; ++i, ++moves) {
            const double v_basic = std::round(
                std::exp(std::log(kBasicPerCps * 1000) + unit(random) * std::log(kVmaxBasic / (kBasicPerCps * 1000))));
            const double v_cps = v_basic / kBasicPerCps;
            const auto rate = [&] {
                const double low = v_cps / 2, high = 5e7;
                return std::max(
                    1.0, std::round(std::exp(std::log(low) + unit(random) * std::log(high / low)) * kBasicPerCps2));
            };
            const double acc = rate(), dec = rate();
            vars.set("ACC", std::int32_t(acc));
            vars.set("DEC", std::int32_t(dec));
            const bool incremental = unit(random) < 0.5;
            const auto distance = std::int64_t(std::round((unit(random) - 0.5) * 2 * std::max(v_cps * 0.5, 2.0)));
            const double from = motion.commandPosition_counts();
            const std::int64_t target = incremental ? distance : std::int64_t(from) + distance;
            ASSERT_EQ(motion.move(vars, true, target, std::int64_t(v_basic), incremental), 0);
            const double maxDv = std::max(acc, dec) / kBasicPerCps2 * peak * 1e-3;
            double last = 0;
            for (int ms = 0; ms < 200'000 && motion.moving(); ++ms) {
                motion.step(1ms, vars);
                const double v = motion.commandVelocity_cps();
                if (std::abs(v) > v_cps * kSlack + 1e-9) ++violations;
                if (std::abs(vars.read("VCMD").value_or(0)) > kVmaxBasic) ++violations;
                if (std::abs(v - last) > maxDv * kSlack + 1e-9) ++violations;
                last = v;
            }
            ASSERT_FALSE(motion.moving());
            const double expected = incremental ? from + double(distance) : double(target);
            ASSERT_EQ(motion.commandPosition_counts(), expected) << "SCRV " << level << " move " << i;
            ASSERT_EQ(vars.read("PCMD").value_or(0), std::int32_t(expected));
            ASSERT_EQ(vars.read("VCMD").value_or(-1), 0);
        }
    }
    EXPECT_EQ(violations, 0) << "speed beyond VMAX/the command or acceleration beyond peak x ACC, " << moves
                             << " moves";
}

TEST(Bds5SCurveProperty, AverageAccelerationIsAccAndThePeakFollowsTheShape) {
    // J 1000 RPM from rest at ACC = 10000 RPM/s: 100 ms of accel for every SCRV (the average), with the
    // shape's peak in the middle and half the speed at half the time (the shapes are symmetric).
    for (int level = 1; level <= 5; ++level) {
        Bds5VariableStore vars = freshStore(level);
        vars.set("ACC", 44739); // 10000 RPM/s in basic units (4.47392 per RPM/s)
        vars.set("DEC", 44739);
        Bds5Motion motion;
        const std::int64_t v = 4473920; // 1000 RPM
        ASSERT_EQ(motion.jog(vars, true, v), 0);
        const double v_cps = double(v) / kBasicPerCps, acc_cps2 = 44739 / kBasicPerCps2;
        int accelMs = 0;
        double peakDv = 0, last = 0, atHalf = 0;
        while (vars.read("SEG").value_or(1) != 2 && accelMs < 1000) {
            motion.step(1ms, vars);
            ++accelMs;
            const double now = motion.commandVelocity_cps();
            peakDv = std::max(peakDv, now - last);
            last = now;
            if (accelMs == 50) atHalf = now;
        }
        EXPECT_NEAR(accelMs, v_cps / acc_cps2 * 1000, 1.0) << "SCRV " << level << ": ACC is the average rate";
        EXPECT_EQ(vars.read("VCMD").value_or(0), 1000) << "RPM";
        const double peak = sCurvePeak(drive_core::motion::sCurveFromLevel(level));
        EXPECT_NEAR(peakDv / (acc_cps2 * 1e-3), peak, 0.02 * peak) << "SCRV " << level << " peak acceleration / ACC";
        EXPECT_NEAR(atHalf, v_cps / 2, v_cps * 0.005) << "SCRV " << level << " symmetric";
    }
}

TEST(Bds5SCurveProperty, SegmentTimesMatchTheFormulasForEveryScrv) {
    // Ta = V/ACC, Tt = (D - V²/2ACC - V²/2DEC)/V, Td = V/DEC; triangular moves keep a short traverse.
    std::mt19937 random(2026'11'22);
    std::uniform_real_distribution<double> unit(0, 1);
    for (int level = 1; level <= 5; ++level) {
        for (int i = 0; i < 60; ++i) {
            Bds5VariableStore vars = freshStore(level);
            Bds5Motion motion;
            const double v_cps = 2000 + unit(random) * 60000;
            const double acc_cps2 = 20000 + unit(random) * 500000, dec_cps2 = 20000 + unit(random) * 500000;
            vars.set("ACC", std::int32_t(std::round(acc_cps2 * kBasicPerCps2)));
            vars.set("DEC", std::int32_t(std::round(dec_cps2 * kBasicPerCps2)));
            const double a = std::round(acc_cps2 * kBasicPerCps2) / kBasicPerCps2;
            const double d = std::round(dec_cps2 * kBasicPerCps2) / kBasicPerCps2;
            const double v = std::round(v_cps * kBasicPerCps) / kBasicPerCps;
            const double ramps = v * v / (2 * a) + v * v / (2 * d);
            const auto distance = std::int64_t(ramps * (1.2 + unit(random) * 3));
            ASSERT_EQ(motion.move(vars, true, distance, std::int64_t(std::round(v * kBasicPerCps)), true), 0);
            const std::vector<int> seg = segmentsPerMs(motion, vars, 100'000);
            const auto ms = [&](int n) { return double(std::count(seg.begin(), seg.end(), n)); };
            EXPECT_NEAR(ms(1), v / a * 1000, 1.0) << "SCRV " << level << " accel";
            EXPECT_NEAR(ms(2), (double(distance) - ramps) / v * 1000, 1.0) << "SCRV " << level << " traverse";
            EXPECT_NEAR(ms(3), v / d * 1000, 1.0) << "SCRV " << level << " decel";
            EXPECT_EQ(motion.commandPosition_counts(), double(distance));
        }
    }
}

TEST(Bds5SCurveProperty, RandomJogsAndMacrosWithEveryScrvStayWithinTheirSpeeds) {
    std::mt19937 random(5'5'2026);
    std::uniform_real_distribution<double> unit(0, 1);
    for (int level = 1; level <= 5; ++level) {
        Bds5VariableStore vars = freshStore(level);
        vars.set("ACC", 20000);
        vars.set("DEC", 30000);
        Bds5Motion motion;
        double top = 0;
        for (int i = 0; i < 50; ++i) { // jogs retargeted at random moments, also mid-ramp
            const auto v = std::int64_t((unit(random) * 2 - 1) * kVmaxBasic);
            ASSERT_EQ(motion.jog(vars, true, v), 0);
            const double prev = top;
            top = std::abs(double(v));
            for (int ms = int(unit(random) * 3000); ms > 0; --ms) {
                motion.step(1ms, vars);
                EXPECT_LE(std::abs(vars.read("VCMD").value_or(0)), std::max(prev, top) + 1);
                EXPECT_LE(std::abs(vars.read("VCMD").value_or(0)), kVmaxBasic);
            }
        }
        ASSERT_EQ(motion.jog(vars, true, 0), 0);
        segmentsPerMs(motion, vars, 100'000);
        // Macro example 1 (L2533-2555) in counts: 11000 counts in 5 segments, whatever the shape.
        vars.set("ACC", 89478); // 20000 RPM/s
        vars.set("DEC", 89478);
        const double start = motion.commandPosition_counts();
        ASSERT_EQ(motion.macroSection(vars, 10000, false, 4473920, 894784), 0);
        ASSERT_EQ(motion.macroSection(vars, 1000, false, 0, std::nullopt), 0);
        ASSERT_EQ(motion.macroGo(vars, true), 0);
        const std::vector<int> seg = segmentsPerMs(motion, vars, 100'000);
        EXPECT_EQ(*std::max_element(seg.begin(), seg.end()), 5) << "SCRV " << level;
        EXPECT_EQ(motion.commandPosition_counts(), start + 11000) << "SCRV " << level;
    }
}

TEST(ProfileGeneratorSCurve, LandsExactlyWhateverTheStepWithEveryShape) {
    std::mt19937 random(22'11'2026);
    std::uniform_real_distribution<double> unit(0, 1);
    for (int level = 1; level <= 5; ++level) {
        drive_core::motion::ProfileGenerator profile;
        for (int i = 0; i < 200; ++i) {
            drive_core::motion::MoveRequest move;
            move.target_counts = std::round((unit(random) - 0.5) * 2e5);
            move.velocity_cps = 1000 + unit(random) * 1e5;
            move.accel_cps2 = 1e4 + unit(random) * 1e6;
            move.decel_cps2 = 1e4 + unit(random) * 1e6;
            move.shape = drive_core::motion::sCurveFromLevel(level);
            ASSERT_TRUE(profile.push(move));
            const double dt = 1e-4 + unit(random) * 2e-3; // any step, not only 1 ms
            for (int n = 0; n < 10'000'000 && profile.moving(); ++n) {
                profile.step(dt);
                ASSERT_LE(std::abs(profile.velocity()), move.velocity_cps * kSlack);
            }
            ASSERT_EQ(profile.position(), move.target_counts) << "SCRV " << level << " move " << i;
            ASSERT_EQ(profile.velocity(), 0);
        }
    }
}
