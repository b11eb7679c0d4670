// Measurements on synthetic signals whose answers are known in closed form: statistics of a sine, the
// rise and settling of a first-order step, the overshoot of a second-order step, steady-state and
// following error, and the step window ending where the command turns back.
#include "scope/signal_analysis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

using scope::analyseStep;
using scope::channelStats;

namespace {

std::vector<double> firstOrder(double tau_s, double dt, std::size_t n, double gain = 1.0, std::size_t delay = 0) {
    std::vector<double> y(n, 0.0);
    for (std::size_t i = delay; i < n; ++i) y[i] = gain * (1.0 - std::exp(-double(i - delay) * dt / tau_s));
    return y;
}

std::vector<double> stepCommand(std::size_t n, std::size_t at, double height = 1.0) {
    std::vector<double> c(n, 0.0);
    for (std::size_t i = at; i < n; ++i) c[i] = height;
    return c;
}

} // namespace

TEST(ChannelStats, SineOverWholePeriods) {
    const double amplitude = 3.0, offset = 1.0;
    std::vector<double> v;
    for (int i = 0; i < 1000; ++i) v.push_back(offset + amplitude * std::sin(2 * std::numbers::pi * i / 100.0));
    const auto s = channelStats(v);
    ASSERT_TRUE(s);
    EXPECT_NEAR(s->mean, offset, 1e-9);
    EXPECT_NEAR(s->rms, std::sqrt(offset * offset + amplitude * amplitude / 2), 1e-9);
    EXPECT_NEAR(s->maximum, offset + amplitude, 1e-9);
    EXPECT_NEAR(s->minimum, offset - amplitude, 1e-9);
    EXPECT_NEAR(s->peakToPeak, 2 * amplitude, 1e-9);
    EXPECT_FALSE(channelStats({}));
}

TEST(StepMetrics, FirstOrderRiseIsTauLn9AndSettlingTauLn50) {
    const double tau = 0.010, dt = 0.0001;
    const auto y = firstOrder(tau, dt, 4000, 1.0, 100);
    const auto cmd = stepCommand(4000, 100);
    const auto m = analyseStep(y, dt, cmd);
    ASSERT_TRUE(m.hasStep);
    EXPECT_NEAR(m.stepStart_s, 99 * dt, 1e-12);
    ASSERT_TRUE(m.rise_s);
    EXPECT_NEAR(*m.rise_s, tau * std::log(9.0), 2 * dt);
    ASSERT_TRUE(m.settling_s);
    EXPECT_NEAR(*m.settling_s, tau * std::log(50.0), 2 * dt);
    EXPECT_NEAR(m.overshoot_pct, 0.0, 1e-9);
    ASSERT_TRUE(m.steadyStateError);
    EXPECT_NEAR(*m.steadyStateError, 0.0, 1e-6);
    ASSERT_TRUE(m.followingErrorPeak);
    EXPECT_NEAR(*m.followingErrorPeak, 1.0, 1e-9); // at the step itself
}

TEST(StepMetrics, SecondOrderOvershootMatchesDampingRatio) {
    const double zeta = 0.5, wn = 2 * std::numbers::pi * 30, dt = 0.00005;
    const double wd = wn * std::sqrt(1 - zeta * zeta), phi = std::acos(zeta);
    std::vector<double> y(8000);
    for (std::size_t i = 0; i < y.size(); ++i) {
        const double t = double(i) * dt;
        y[i] = 1 - std::exp(-zeta * wn * t) * std::sin(wd * t + phi) / std::sqrt(1 - zeta * zeta);
    }
    const auto m = analyseStep(y, dt);
    ASSERT_TRUE(m.hasStep);
    const double expected = 100 * std::exp(-std::numbers::pi * zeta / std::sqrt(1 - zeta * zeta));
    EXPECT_NEAR(m.overshoot_pct, expected, 0.05);
    ASSERT_TRUE(m.settling_s);
    // The 2 % envelope bound: settles no later than ln(50/sqrt(1-zeta^2)) / (zeta wn).
    EXPECT_LE(*m.settling_s, std::log(50 / std::sqrt(1 - zeta * zeta)) / (zeta * wn) + dt);
    EXPECT_GE(*m.settling_s, 2.0 / (zeta * wn));
    EXPECT_FALSE(m.steadyStateError); // no command given
}

TEST(StepMetrics, SteadyStateErrorIsCommandMinusFinal) {
    const auto y = firstOrder(0.005, 0.001, 500, 950.0, 10);
    const auto cmd = stepCommand(500, 10, 1000.0);
    const auto m = analyseStep(y, 0.001, cmd);
    ASSERT_TRUE(m.steadyStateError);
    EXPECT_NEAR(*m.steadyStateError, 50.0, 1e-6);
    EXPECT_NEAR(m.finalValue, 950.0, 1e-6);
}

TEST(StepMetrics, FollowingErrorPeakOfADelayedRamp) {
    // Command ramps at 2 units per sample; the response lags 5 samples: error 10 while ramping.
    std::vector<double> cmd(300), y(300);
    for (std::size_t i = 0; i < 300; ++i) {
        cmd[i] = i < 100 ? 2.0 * double(i) : 200.0;
        y[i] = i < 5 ? 0.0 : cmd[i - 5];
    }
    const auto m = analyseStep(y, 0.001, cmd);
    ASSERT_TRUE(m.followingErrorPeak);
    EXPECT_NEAR(*m.followingErrorPeak, 10.0, 1e-9);
}

TEST(StepMetrics, WindowEndsWhereTheCommandTurnsBack) {
    // J 1000 for 200 samples, then J 0: the step is measured on the plateau, not the whole record.
    std::vector<double> cmd(400, 0.0), y(400, 0.0);
    for (std::size_t i = 20; i < 220; ++i) cmd[i] = 1000.0;
    const auto up = firstOrder(0.010, 0.001, 400, 1000.0, 20);
    for (std::size_t i = 0; i < 220; ++i) y[i] = up[i];
    for (std::size_t i = 220; i < 400; ++i) y[i] = y[219] * std::exp(-double(i - 219) * 0.001 / 0.010);
    const auto m = analyseStep(y, 0.001, cmd);
    ASSERT_TRUE(m.hasStep);
    EXPECT_NEAR(m.windowEnd_s, 0.219, 1e-9);
    EXPECT_NEAR(m.finalValue, 1000.0, 0.1);
    ASSERT_TRUE(m.rise_s);
    EXPECT_NEAR(*m.rise_s, 0.010 * std::log(9.0), 0.002);
}

TEST(StepMetrics, NegativeStepsMeasureLikePositiveOnes) {
    const auto up = analyseStep(firstOrder(0.01, 0.001, 300, 500.0, 10), 0.001, stepCommand(300, 10, 500.0));
    const auto down = analyseStep(firstOrder(0.01, 0.001, 300, -500.0, 10), 0.001, stepCommand(300, 10, -500.0));
    ASSERT_TRUE(up.rise_s && down.rise_s && up.settling_s && down.settling_s);
    EXPECT_NEAR(*up.rise_s, *down.rise_s, 1e-12);
    EXPECT_NEAR(*up.settling_s, *down.settling_s, 1e-12);
    EXPECT_NEAR(down.overshoot_pct, 0.0, 1e-9);
}

TEST(StepMetrics, AFlatRecordHasNoStep) {
    const std::vector<double> flat(100, 42.0);
    EXPECT_FALSE(analyseStep(flat, 0.001).hasStep);
    EXPECT_FALSE(analyseStep(flat, 0.001, flat).hasStep);
}

TEST(StepMetrics, NotSettledWhenStillRingingAtTheEnd) {
    std::vector<double> y(200);
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = i < 10 ? 0.0 : 1.0 + 0.2 * std::sin(double(i));
    const auto m = analyseStep(y, 0.001, stepCommand(200, 10));
    ASSERT_TRUE(m.hasStep);
    EXPECT_FALSE(m.settling_s);
}
