// Property tests with fixed seeds on the BDS5's motion commands (Bds5Motion on the profile generator):
// thousands of random MA / MI / J profiles, JT / JF speed changes and macro moves (MCI / MCA / MCD / MCGO) land
// exactly on their target count at the times the formulas give, never exceed VMAX or the commanded speed, and
// never change speed faster than ACC / DEC allow in a 1 ms servo period.
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

namespace {
// A log-uniform draw between low and high.
double logUniform(std::mt19937& random, double low, double high) {
    return std::exp(std::log(low) + std::uniform_real_distribution<double>(0, 1)(random) * std::log(high / low));
}
int seg(const Bds5VariableStore& vars) {
    return vars.read("SEG").value_or(-1);
}
} // namespace

// JT / JF (L2734-2800) from a random jog: the hold lasts (distance - ramp distance) / v0 (JT) or
// distance / v0 (JF), the speed change |v1 - v0| / rate; JT's change ends exactly at its position (so a JT
// to 0 stops on the count), JF's begins exactly there; never beyond VMAX or the rate in any period.
TEST(Bds5MotionProperty, RandomJtJfLandOnTheirPositionAfterTheFormulaTimes) {
    std::mt19937 random(11'2026'4);
    std::uniform_real_distribution<double> unit(0, 1);
    Bds5VariableStore vars = freshStore();
    Bds5Motion motion;
    int violations = 0, stops = 0;
    for (int i = 0; i < 600; ++i) {
        const double direction = unit(random) < 0.5 ? -1 : 1;
        const double v0_basic = direction * std::round(logUniform(random, 4e4, kVmaxBasic));
        const double v1_basic = unit(random) < 0.3 ? 0 : direction * std::round(logUniform(random, 4e4, kVmaxBasic));
        const double v0 = v0_basic / kBasicPerCps, v1 = v1_basic / kBasicPerCps;
        const double acc_basic = std::round(logUniform(random, kVmaxBasic / kBasicPerCps / 2, 5e7) * kBasicPerCps2);
        const double dec_basic = std::round(logUniform(random, kVmaxBasic / kBasicPerCps / 2, 5e7) * kBasicPerCps2);
        vars.set("ACC", std::int32_t(acc_basic));
        vars.set("DEC", std::int32_t(dec_basic));
        const double acc = acc_basic / kBasicPerCps2, dec = dec_basic / kBasicPerCps2;
        const Limits limits{acc, dec, std::max(std::abs(v0), std::abs(v1))};
        ASSERT_EQ(motion.jog(vars, true, std::int64_t(v0_basic)), 0);
        const auto atSpeed = [&] { return std::abs(motion.commandVelocity_cps() - v0) <= 1e-9 * std::abs(v0); };
        for (int ms = 0; ms < 100'000 && !atSpeed(); ++ms) motion.step(1ms, vars);
        ASSERT_TRUE(atSpeed()) << "jog " << i;

        const bool to = unit(random) < 0.6;
        const double rate = std::abs(v1) > std::abs(v0) ? acc : dec;
        const double ramp_s = std::abs(v1 - v0) / rate;
        const double rampDistance = (v0 + v1) / 2 * ramp_s;
        const double hold_s = 0.005 + unit(random) * 0.5;
        const double from = motion.commandPosition_counts();
        const auto position = std::int64_t(std::round(from + v0 * hold_s + (to ? rampDistance : 0)));
        ASSERT_EQ(motion.jogTo(vars, true, position, std::int64_t(v1_basic), to), 0) << (to ? "JT " : "JF ") << i;
        // The formulas, from the rounded position.
        const double hold = ((double(position) - from) - (to ? rampDistance : 0)) / v0;
        int segmentTwoAt = -1, segmentThreeAt = -1, ms = 0;
        double last = motion.commandVelocity_cps();
        while (ms < 10'000 && motion.moving() && seg(vars) != 3) {
            motion.step(1ms, vars);
            ++ms;
            const double v = motion.commandVelocity_cps();
            if (std::abs(v) > limits.speed_cps * kSlack + 1e-9 || std::abs(v) > kVmaxBasic / kBasicPerCps * kSlack)
                ++violations;
            if (std::abs(v - last) > rate * 1e-3 * kSlack + 1e-9) ++violations;
            last = v;
            if ((seg(vars) >= 2 || !motion.moving()) && segmentTwoAt < 0) segmentTwoAt = ms;
            if ((seg(vars) == 3 || !motion.moving()) && segmentThreeAt < 0) segmentThreeAt = ms;
        }
        const double t = ms * 1e-3;
        EXPECT_NEAR(segmentTwoAt * 1e-3, hold, 1e-3 + 1e-9) << "hold time, " << i;
        EXPECT_NEAR(segmentThreeAt * 1e-3, hold + ramp_s, 1e-3 + 1e-9) << "ramp time, " << i;
        const double rampEnd = to ? double(position) : double(position) + rampDistance;
        if (v1 == 0) {
            ASSERT_FALSE(motion.moving()) << i;
            if (to) {
                EXPECT_EQ(motion.commandPosition_counts(), double(position)) << "JT 0 stops on the count, " << i;
            }
            EXPECT_NEAR(motion.commandPosition_counts(), rampEnd, 1e-6 * std::abs(rampEnd) + 1e-6) << i;
            ++stops;
        } else { // at v1 since hold + ramp: where it is now says where the change ended
            EXPECT_NEAR(motion.commandVelocity_cps(), v1, 1e-9 * std::abs(v1)) << i;
            const double ended = motion.commandPosition_counts() - v1 * (t - hold - ramp_s);
            EXPECT_NEAR(ended, rampEnd, 1e-6 * std::abs(rampEnd) + 1e-6) << "the change ends at the position, " << i;
            motion.jog(vars, true, 0);
            runChecked(motion, vars, {acc, dec, limits.speed_cps}, 100'000, violations);
        }
        motion.normalize(0); // keep positions within a few million counts
    }
    EXPECT_EQ(violations, 0);
    EXPECT_GT(stops, 100);
}

// Random macro moves (MCI, MCA, MCD, MCGO; L2496-2579): sections of one, two or no velocities, dwells
// where they are allowed, ACC and DEC changed between sections. Each macro lands exactly on the sum of its
// sections, each segment starts when the formulas say (ramps |Δv| / rate, traverses distance / speed,
// dwells), and no period goes faster than the sections' speeds or changes speed faster than their rates.
TEST(Bds5MotionProperty, RandomMacroMovesLandOnTheirCountAtTheFormulaTimes) {
    std::mt19937 random(2026'4'11);
    std::uniform_real_distribution<double> unit(0, 1);
    Bds5VariableStore vars = freshStore();
    Bds5Motion motion;
    int violations = 0, lateSegments = 0, checkedSegments = 0;
    for (int m = 0; m < 300; ++m) {
        motion.resetMacro();
        const double start = motion.commandPosition_counts();
        double defined = 0, speed = 0; // the macro's distance so far and its speed at the end (signed, cps)
        double topSpeed = 0, topRate = 0;
        std::vector<double> durations; // every segment the formulas give, in order (zero-length ones left out)
        const auto addDuration = [&](double d) {
            if (d > 0) durations.push_back(d);
        };
        const int sections = 1 + int(unit(random) * 5);
        for (int k = 0; k <= sections; ++k) {
            const bool last = k == sections;
            if (last && speed == 0) break;
            if (speed == 0 && unit(random) < 0.3) { // MCD
                const auto ms = std::int64_t(1 + unit(random) * 200);
                ASSERT_EQ(motion.macroDwell(ms), 0);
                addDuration(double(ms) / 1000);
            }
            const double acc_basic = std::round(logUniform(random, 1e4, 5e7) * kBasicPerCps2);
            const double dec_basic = std::round(logUniform(random, 1e4, 5e7) * kBasicPerCps2);
            vars.set("ACC", std::int32_t(acc_basic));
            vars.set("DEC", std::int32_t(dec_basic));
            const double acc = acc_basic / kBasicPerCps2, dec = dec_basic / kBasicPerCps2;
            const double direction = speed != 0 ? (speed < 0 ? -1 : 1) : (unit(random) < 0.5 ? -1 : 1);
            const double s = std::abs(speed);
            const auto draw = [&] { return std::round(logUniform(random, 2e4, kVmaxBasic / 4)); };
            std::optional<std::int64_t> first, second;
            double traverse = s, end = s;
            const double form = unit(random);
            if (last) { // the closing section: one velocity, 0
                first = 0;
                end = 0;
            } else if (form < 0.4 || s == 0) { // traverse and end
                first = std::int64_t(draw());
                second = unit(random) < 0.4 ? 0 : std::int64_t(draw());
                traverse = double(*first) / kBasicPerCps;
                end = double(*second) / kBasicPerCps;
            } else if (form < 0.8) { // the end speed; the traverse is the faster of start and end
                first = unit(random) < 0.4 ? 0 : std::int64_t(draw());
                end = double(*first) / kBasicPerCps;
                traverse = std::max(s, end);
            } // else: no velocity, at the start speed throughout
            const double rate1 = traverse > s ? acc : dec, rate2 = end > traverse ? acc : dec;
            const double ramps = std::abs(traverse * traverse - s * s) / (2 * rate1) +
                                 std::abs(end * end - traverse * traverse) / (2 * rate2);
            const double distance = std::ceil(ramps + 1 + unit(random) * traverse * 0.3);
            const bool absolute = unit(random) < 0.5;
            const double target = absolute ? start + defined + direction * distance : direction * distance;
            ASSERT_EQ(motion.macroSection(vars, std::int64_t(target), absolute, first, second), 0)
                << "macro " << m << " section " << k;
            addDuration(std::abs(traverse - s) / rate1);
            addDuration((distance - ramps) / traverse);
            addDuration(std::abs(end - traverse) / rate2);
            topSpeed = std::max({topSpeed, traverse, s});
            topRate = std::max({topRate, rate1, rate2});
            defined += direction * distance;
            speed = direction * end;
        }
        ASSERT_EQ(motion.macroGo(vars, true), 0) << "macro " << m;
        // Step through, noting when each segment number first shows.
        std::vector<int> firstSeen(durations.size() + 2, -1);
        double lastV = 0;
        int ms = 0;
        while (motion.moving() && ms < 1'000'000) {
            motion.step(1ms, vars);
            ++ms;
            const double v = motion.commandVelocity_cps();
            if (std::abs(v) > topSpeed * kSlack + 1e-9) ++violations;
            if (std::abs(v - lastV) > topRate * 1e-3 * kSlack + 1e-9) ++violations;
            lastV = v;
            const int n = seg(vars);
            if (n >= 1 && n < int(firstSeen.size()) && firstSeen[std::size_t(n)] < 0) firstSeen[std::size_t(n)] = ms;
        }
        ASSERT_FALSE(motion.moving());
        EXPECT_EQ(motion.commandPosition_counts(), start + defined) << "macro " << m << " lands on the count";
        EXPECT_EQ(vars.read("PFNL").value_or(0), std::int32_t(start + defined));
        double at = 0;
        for (std::size_t k = 0; k < durations.size(); ++k) {
            if (k > 0 && firstSeen[k + 1] >= 0) { // segment k+1 starts once the first k are over
                ++checkedSegments;
                if (std::abs(firstSeen[k + 1] * 1e-3 - at) > 1e-3 + 1e-9) ++lateSegments;
            }
            at += durations[k];
        }
        EXPECT_NEAR(ms * 1e-3, at, 1e-3 + 1e-9) << "macro " << m << " takes the sum of its segments";
        if (std::abs(start + defined) > 1e8) motion.normalize(0);
    }
    EXPECT_EQ(violations, 0);
    EXPECT_EQ(lateSegments, 0) << "of " << checkedSegments << " segment starts";
    EXPECT_GT(checkedSegments, 500);
}
