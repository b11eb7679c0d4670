// Frequency response estimate on systems simulated here with known bandwidth: a first-order and a
// second-order (zeta = 0.707) velocity loop driven by a step, a step-and-back with seeded noise, a chirp.
#include "scope/frequency_response.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <random>

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kDt = 0.001; // RECORD at 1 ms, as the tuning panel's Bode preset

// Continuous system stepped with 20 sub-steps per sample (semi-implicit Euler), input held between samples.
struct SecondOrder {
    double wn, zeta;
    double y = 0, v = 0;
    double step(double u) {
        const double h = kDt / 20;
        for (int i = 0; i < 20; ++i) {
            v += h * (wn * wn * (u - y) - 2 * zeta * wn * v);
            y += h * v;
        }
        return y;
    }
};
struct FirstOrder {
    double wc;
    double y = 0;
    double step(double u) { return y += (1 - std::exp(-wc * kDt)) * (u - y); }
};

template <class System> std::vector<double> simulate(System system, const std::vector<double>& input) {
    std::vector<double> out;
    for (const double u : input) out.push_back(system.step(u));
    return out;
}

// The tuning panel's Bode preset: J v a few samples after RECORD starts, held to the end of the record.
std::vector<double> stepInput(std::size_t n, std::size_t at = 8, double amplitude = 100) {
    std::vector<double> x(n, 0);
    for (std::size_t i = at; i < n; ++i) x[i] = amplitude;
    return x;
}

void expectWithin(double value, double expected, double fraction) {
    EXPECT_GT(value, expected * (1 - fraction));
    EXPECT_LT(value, expected * (1 + fraction));
}
} // namespace

TEST(FrequencyResponse, FirstOrderStepGivesItsBandwidthAndNinetyDegreesOfMargin) {
    const double fc = 30;
    const std::vector<double> x = stepInput(500);
    const auto r = scope::estimateFrequencyResponse(x, simulate(FirstOrder{2 * kPi * fc}, x), kDt);
    ASSERT_EQ(r.status, scope::FrequencyResponse::Status::Ok) << r.error;
    EXPECT_NEAR(r.reference_db, 0, 0.5);
    ASSERT_TRUE(r.bandwidth_hz);
    expectWithin(*r.bandwidth_hz, fc, 0.10);
    ASSERT_TRUE(r.phaseAtBandwidth_deg);
    EXPECT_NEAR(*r.phaseAtBandwidth_deg, -45, 10); // one pole: -45 degrees at the corner
    // Closed loop wc / (s + wc) is the unity feedback of L = wc / s: crossover at fc, 90 degrees of margin.
    ASSERT_TRUE(r.phaseMargin_deg) << r.marginNote;
    EXPECT_NEAR(*r.phaseMargin_deg, 90, 10);
    expectWithin(*r.crossover_hz, fc, 0.10);
}

TEST(FrequencyResponse, SecondOrderButterworthStepGivesItsNaturalFrequency) {
    const double fn = 40; // zeta = 1/sqrt(2): the -3 dB bandwidth is the natural frequency
    const std::vector<double> x = stepInput(500);
    const auto r = scope::estimateFrequencyResponse(x, simulate(SecondOrder{2 * kPi * fn, 1 / std::sqrt(2.0)}, x), kDt);
    ASSERT_EQ(r.status, scope::FrequencyResponse::Status::Ok) << r.error;
    ASSERT_TRUE(r.bandwidth_hz);
    expectWithin(*r.bandwidth_hz, fn, 0.10);
    EXPECT_NEAR(*r.phaseAtBandwidth_deg, -90, 12);
    // L = wn^2 / (s (s + 2 zeta wn)): the margin is atan(2 zeta / sqrt(sqrt(1 + 4 zeta^4) - 2 zeta^2)).
    const double z = 1 / std::sqrt(2.0);
    const double expected = std::atan(2 * z / std::sqrt(std::sqrt(1 + 4 * z * z * z * z) - 2 * z * z)) * 180 / kPi;
    ASSERT_TRUE(r.phaseMargin_deg) << r.marginNote;
    EXPECT_NEAR(*r.phaseMargin_deg, expected, 8);
}

TEST(FrequencyResponse, StepAndBackWithNoiseStillGivesTheBandwidth) {
    // The tuning runs' velocity step (J v, then J 0 halfway): the input spectrum has zeros every 1 / T,
    // which are dropped; feedback noise of 0.5 % of the step, seeded.
    const double fn = 25;
    std::vector<double> x(400, 0);
    for (std::size_t i = 6; i < 206; ++i) x[i] = 1000;
    std::vector<double> y = simulate(SecondOrder{2 * kPi * fn, 0.8}, x);
    std::mt19937 random(6);
    std::normal_distribution<double> noise(0, 5);
    for (double& v : y) v += noise(random);
    const auto r = scope::estimateFrequencyResponse(x, y, kDt);
    ASSERT_EQ(r.status, scope::FrequencyResponse::Status::Ok) << r.error;
    // zeta = 0.8: |H| = 1/sqrt(2) at wn * sqrt(1 - 2 z^2 + sqrt(4 z^4 - 4 z^2 + 2)).
    const double z = 0.8;
    const double expected = fn * std::sqrt(1 - 2 * z * z + std::sqrt(4 * z * z * z * z - 4 * z * z + 2));
    ASSERT_TRUE(r.bandwidth_hz);
    expectWithin(*r.bandwidth_hz, expected, 0.10);
}

TEST(FrequencyResponse, ChirpInputGivesTheBandwidth) {
    const double fc = 20;
    std::vector<double> x;
    for (int i = 0; i < 2000; ++i) {
        const double t = i * kDt; // 0.5 Hz to 100 Hz in 2 s
        x.push_back(50 * std::sin(2 * kPi * (0.5 * t + 0.5 * 99.5 / 2 * t * t)));
    }
    scope::FrequencyResponseOptions options;
    options.difference = false; // a chirp is broadband as it is
    const auto r = scope::estimateFrequencyResponse(x, simulate(FirstOrder{2 * kPi * fc}, x), kDt, options);
    ASSERT_EQ(r.status, scope::FrequencyResponse::Status::Ok) << r.error;
    ASSERT_TRUE(r.bandwidth_hz);
    expectWithin(*r.bandwidth_hz, fc, 0.10);
}

TEST(FrequencyResponse, ConstantInputIsRefusedWithAReason) {
    const std::vector<double> x(300, 100);
    const auto r = scope::estimateFrequencyResponse(x, x, kDt);
    EXPECT_EQ(r.status, scope::FrequencyResponse::Status::NoExcitation);
    EXPECT_FALSE(r.error.empty());
    EXPECT_EQ(scope::estimateFrequencyResponse({1, 2}, {1, 2}, kDt).status, scope::FrequencyResponse::Status::TooShort);
}

TEST(FrequencyResponse, GainNotUnityGivesNoMarginButSaysWhy) {
    const std::vector<double> x = stepInput(500);
    std::vector<double> y = simulate(FirstOrder{2 * kPi * 30}, x);
    for (double& v : y) v *= 0.5; // -6 dB: not a unity-feedback loop
    const auto r = scope::estimateFrequencyResponse(x, y, kDt);
    ASSERT_TRUE(r.bandwidth_hz);
    expectWithin(*r.bandwidth_hz, 30, 0.10);
    EXPECT_FALSE(r.phaseMargin_deg);
    EXPECT_NE(r.marginNote.find("not 0 dB"), std::string::npos);
}
