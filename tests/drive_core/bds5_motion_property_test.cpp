// Property tests with fixed seeds on the BDS5's motion commands (Bds5Motion on the profile generator):
// thousands of random MA / MI / J profiles land exactly on their target count, never exceed VMAX or the
// commanded speed, and never change speed faster than ACC / DEC allow in a 1 ms servo period.
#include "drive_core/bds5/bds5_motion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using drive_core::bds5::Bds5Motion;
using drive_core::bds5::Bds5VariableStore;
using namespace std::chrono_literals;

namespace {
constexpr double kBasicPerCps = 65.536;    // velocity: 1/65536 count per ms
constexpr double kBasicPerCps2 = 0.065536; // acceleration: 1/65536 count per ms²
constexpr double kVmaxBasic = 33554250;    // 7500 RPM, the power-up VMAX
constexpr double kSlack = 1 + 1e-9;

struct Limits {
    double accel_cps2, decel_cps2, speed_cps;
};

// Steps until motion stops (at most maxMs), checking speed and acceleration every period.
void runChecked(Bds5Motion& motion, Bds5VariableStore& vars, const Limits& limit, int maxMs, int& violations) {
    double last = motion.commandVelocity_cps();
    for (int ms = 0; ms < maxMs && motion.moving(); ++ms) {
        motion.step(1ms, vars);
        const double v = motion.commandVelocity_cps();
        if (std::abs(v) > limit.speed_cps * kSlack + 1e-9) ++violations;
        if (std::abs(v - last) > std::max(limit.accel_cps2, limit.decel_cps2) * 1e-3 * kSlack + 1e-9) ++violations;
        last = v;
    }
}

Bds5VariableStore freshStore() {
    Bds5VariableStore vars;
    vars.set("PLIM", 0);
    vars.set("SCRV", 1); // straight lines: ACC/DEC bound every period (S-curves: bds5_scurve_property_test)
    return vars;
}
} // namespace

TEST(Bds5MotionProperty, RandomMaMiMovesLandOnTheirCountWithinVmaxAndAcc) {
    std::mt19937 random(4'2026'11);
    std::uniform_real_distribution<double> unit(0, 1);
    Bds5VariableStore vars = freshStore();
    Bds5Motion motion;
    int violations = 0;
    constexpr int kMoves = 2000;
    for (int i = 0; i < kMoves; ++i) {
        // Speeds from 1 count/ms to VMAX, log-uniform; rates so no ramp lasts longer than 2 s.
        const double v_basic = std::round(
            std::exp(std::log(kBasicPerCps * 1000) + unit(random) * std::log(kVmaxBasic / (kBasicPerCps * 1000))));
        const double v_cps = v_basic / kBasicPerCps;
        const auto rate = [&] {
            const double low = v_cps / 2, high = 5e7;
            return std::round(std::exp(std::log(low) + unit(random) * std::log(high / low)) * kBasicPerCps2);
        };
        const double acc_basic = std::max(rate(), 1.0), dec_basic = std::max(rate(), 1.0);
        vars.set("ACC", std::int32_t(acc_basic));
        vars.set("DEC", std::int32_t(dec_basic));
        const bool incremental = unit(random) < 0.5;
        const auto distance = std::int64_t(std::round((unit(random) - 0.5) * 2 * std::max(v_cps * 0.5, 2.0)));
        const double from = motion.commandPosition_counts();
        const std::int64_t target = incremental ? distance : std::int64_t(from) + distance;
        const int e = motion.move(vars, true, target, std::int64_t(v_basic), incremental);
        ASSERT_EQ(e, 0) << "move " << i;
        runChecked(motion, vars, {acc_basic / kBasicPerCps2, dec_basic / kBasicPerCps2, v_cps}, 200'000, violations);
        ASSERT_FALSE(motion.moving()) << "move " << i;
        const double expected = incremental ? from + double(distance) : double(target);
        ASSERT_EQ(motion.commandPosition_counts(), expected) << "move " << i;
        ASSERT_EQ(vars.read("PCMD").value_or(0), std::int32_t(expected)) << "PCMD lands on the count";
        ASSERT_EQ(vars.read("VCMD").value_or(-1), 0);
    }
    EXPECT_EQ(violations, 0) << "speed or acceleration beyond the limits, over " << kMoves << " moves";
}

TEST(Bds5MotionProperty, RandomJogsStayWithinVmaxAndTheirRates) {
    std::mt19937 random(7'2026'11);
    std::uniform_real_distribution<double> unit(0, 1);
    Bds5VariableStore vars = freshStore();
    Bds5Motion motion;
    int violations = 0;
    for (int i = 0; i < 2000; ++i) {
        const double v_basic = std::round((unit(random) * 2 - 1) * kVmaxBasic);
        const double acc_basic = std::round(std::exp(std::log(5e4) + unit(random) * std::log(1e3)));
        const double dec_basic = std::round(std::exp(std::log(5e4) + unit(random) * std::log(1e3)));
        vars.set("ACC", std::int32_t(acc_basic));
        vars.set("DEC", std::int32_t(dec_basic));
        ASSERT_EQ(motion.jog(vars, true, std::int64_t(v_basic)), 0) << "jog " << i;
        double last = motion.commandVelocity_cps();
        const int ms = 1 + int(unit(random) * 300);
        for (int k = 0; k < ms; ++k) {
            motion.step(1ms, vars);
            const double v = motion.commandVelocity_cps();
            if (std::abs(v) > kVmaxBasic / kBasicPerCps * kSlack) ++violations;
            if (std::abs(v - last) > std::max(acc_basic, dec_basic) / kBasicPerCps2 * 1e-3 * kSlack + 1e-9)
                ++violations;
            // Between the old and the new speed: a jog never overshoots its target.
            last = v;
        }
        if (unit(random) < 0.1) { // now and then J 0 to rest, then the next jog starts from standstill
            motion.jog(vars, true, 0);
            runChecked(motion, vars, {acc_basic / kBasicPerCps2, dec_basic / kBasicPerCps2, kVmaxBasic / kBasicPerCps},
                       100'000, violations);
            EXPECT_EQ(motion.commandVelocity_cps(), 0);
        }
    }
    EXPECT_EQ(violations, 0);
}
