// Math channels against closed forms: d/dt sin = w cos within the central difference's error bound, the
// integral of a constant is a ramp, the moving average of a step is a ramp N samples long, sums and
// following error sample by sample; units carried through and mismatches refused; store channels at
// their own (uneven) times.
#include "scope/math_channel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

using namespace scope;

namespace {

constexpr double kPi = std::numbers::pi;

CaptureChannel sineChannel(double amplitude, double f_hz, double dt, std::size_t n, const std::string& unit = "rpm") {
    CaptureChannel c{"VFB", unit, {}};
    for (std::size_t i = 0; i < n; ++i) c.values.push_back(amplitude * std::sin(2 * kPi * f_hz * double(i) * dt));
    return c;
}

} // namespace

TEST(MathUnits, DerivativeDividesAndIntegralMultipliesBySeconds) {
    EXPECT_EQ(derivativeUnit("rpm"), "rpm/s");
    EXPECT_EQ(derivativeUnit("rpm/s"), "rpm/s²");
    EXPECT_EQ(derivativeUnit("rpm·s"), "rpm");
    EXPECT_EQ(derivativeUnit(""), "1/s");
    EXPECT_EQ(integralUnit("rpm"), "rpm·s");
    EXPECT_EQ(integralUnit("rpm/s"), "rpm");
    EXPECT_EQ(integralUnit("rpm/s²"), "rpm/s");
    EXPECT_EQ(integralUnit(""), "s");
    EXPECT_EQ(integralUnit("1/s"), "");
    EXPECT_EQ(derivativeUnit("s"), "");
    EXPECT_EQ(integralUnit("s"), "s²");
    for (const std::string u : {"VEL", "I", "counts/s", "", "A·s²"}) {
        EXPECT_EQ(integralUnit(derivativeUnit(u)), u);
        EXPECT_EQ(derivativeUnit(integralUnit(u)), u);
    }
}

TEST(MathChannel, DerivativeOfSineIsOmegaCosine) {
    const double a = 3.0, f = 5.0, dt = 0.001, w = 2 * kPi * f;
    const auto c = sineChannel(a, f, dt, 1000);
    const CaptureMath d = derivative(c, dt);
    ASSERT_TRUE(d.ok()) << d.error;
    EXPECT_EQ(d.channel.unit, "rpm/s");
    EXPECT_EQ(d.channel.name, "d/dt(VFB)");
    ASSERT_EQ(d.channel.values.size(), c.values.size());
    // Central difference of A sin(w t): A w cos(w t) sin(w dt) / (w dt); error at most A w^3 dt^2 / 6.
    const double centralBound = a * w * w * w * dt * dt / 6 + 1e-9;
    for (std::size_t i = 1; i + 1 < c.values.size(); ++i)
        ASSERT_NEAR(d.channel.values[i], a * w * std::cos(w * double(i) * dt), centralBound) << "sample " << i;
    // One-sided ends: error at most A w^2 dt / 2 (plus the central-order term).
    const double endBound = a * w * w * dt / 2 + centralBound;
    EXPECT_NEAR(d.channel.values.front(), a * w, endBound);
    EXPECT_NEAR(d.channel.values.back(), a * w * std::cos(w * 999 * dt), endBound);
}

TEST(MathChannel, IntegralOfConstantIsRamp) {
    const double c = 2.5, dt = 0.004;
    const CaptureChannel k{"ICMD", "A", std::vector<double>(500, c)};
    const CaptureMath r = integral(k, dt);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.channel.unit, "A·s");
    for (std::size_t i = 0; i < k.values.size(); ++i) ASSERT_NEAR(r.channel.values[i], c * double(i) * dt, 1e-9);
}

TEST(MathChannel, IntegralOfCosineIsSineOverOmega) {
    const double f = 2.0, dt = 0.001, w = 2 * kPi * f;
    CaptureChannel c{"V", "", {}};
    for (int i = 0; i < 2000; ++i) c.values.push_back(std::cos(w * i * dt));
    const CaptureMath r = integral(c, dt);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.channel.unit, "s");
    // Trapezoid error over [0, T] is at most T w^2 dt^2 / 12 for a function with |f''| <= w^2.
    const double bound = 2.0 * w * w * dt * dt / 12 + 1e-12;
    for (std::size_t i = 0; i < c.values.size(); ++i)
        ASSERT_NEAR(r.channel.values[i], std::sin(w * double(i) * dt) / w, bound) << "sample " << i;
}

TEST(MathChannel, MovingAverageOfStepRampsOverNSamples) {
    const std::size_t n = 8, at = 20;
    const double h = 4.0;
    CaptureChannel step{"VCMD", "VEL", std::vector<double>(60, 0.0)};
    for (std::size_t i = at; i < step.values.size(); ++i) step.values[i] = h;
    const CaptureMath r = movingAverage(step, n);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.channel.unit, "VEL");
    EXPECT_EQ(r.channel.name, "avg8(VCMD)");
    for (std::size_t i = 0; i < step.values.size(); ++i) {
        const double expected = i < at ? 0.0 : i - at + 1 < n ? h * double(i - at + 1) / double(n) : h;
        ASSERT_NEAR(r.channel.values[i], expected, 1e-12) << "sample " << i;
    }
    // At the start the window holds only the samples so far: a constant stays constant.
    const CaptureMath flat = movingAverage(CaptureChannel{"X", "", std::vector<double>(5, 7.0)}, 100);
    for (double v : flat.channel.values) EXPECT_DOUBLE_EQ(v, 7.0);
    EXPECT_EQ(movingAverage(step, 0).status, MathStatus::BadParameter);
}

TEST(MathChannel, SumDifferenceScaleSampleBySample) {
    const CaptureChannel a{"A", "VEL", {1, 2, 3}}, b{"B", "VEL", {10, 20, 40}};
    const CaptureMath s = sum(a, b), d = difference(a, b), k = scaled(a, -2.0);
    ASSERT_TRUE(s.ok() && d.ok() && k.ok());
    EXPECT_EQ(s.channel.values, (std::vector<double>{11, 22, 43}));
    EXPECT_EQ(d.channel.values, (std::vector<double>{-9, -18, -37}));
    EXPECT_EQ(k.channel.values, (std::vector<double>{-2, -4, -6}));
    EXPECT_EQ(s.channel.name, "A+B");
    EXPECT_EQ(d.channel.name, "A-B");
    EXPECT_EQ(k.channel.name, "-2*A");
    EXPECT_EQ(s.channel.unit, "VEL");
    EXPECT_EQ(k.channel.unit, "VEL");
    EXPECT_EQ(scaled(a, 1.0 / 4096, "rev").channel.unit, "rev");
    EXPECT_EQ(scaled(a, std::nan("")).status, MathStatus::BadParameter);
}

TEST(MathChannel, DifferentUnitsAreRefusedNamingBoth) {
    const CaptureChannel v{"VFB", "rpm", {1, 2}}, i{"ICMD", "A", {1, 2}};
    for (const CaptureMath& r : {sum(v, i), difference(v, i), followingError(v, i)}) {
        EXPECT_EQ(r.status, MathStatus::UnitMismatch);
        EXPECT_NE(r.error.find("rpm"), std::string::npos) << r.error;
        EXPECT_NE(r.error.find("ICMD"), std::string::npos) << r.error;
    }
    EXPECT_EQ(sum(v, CaptureChannel{"X", "rpm", {1}}).status, MathStatus::LengthMismatch);
}

TEST(MathChannel, FollowingErrorIsCommandMinusFeedback) {
    const double dt = 0.001;
    CaptureChannel cmd{"VCMD", "VEL", {}}, fb{"VFB", "VEL", {}};
    for (int i = 0; i < 100; ++i) {
        cmd.values.push_back(i < 10 ? 0 : 100);
        fb.values.push_back(i < 10 ? 0 : 100 * (1 - std::exp(-(i - 10) * dt / 0.005)));
    }
    const CaptureMath fe = followingError(cmd, fb);
    ASSERT_TRUE(fe.ok());
    EXPECT_EQ(fe.channel.name, "FE(VCMD-VFB)");
    EXPECT_EQ(fe.channel.unit, "VEL");
    for (int i = 10; i < 100; ++i) ASSERT_NEAR(fe.channel.values[i], 100 * std::exp(-(i - 10) * dt / 0.005), 1e-9);
}

TEST(MathChannel, EvaluateFindsOperandsByNameAndRenames) {
    Capture c;
    c.interval_s = 0.5;
    c.channels = {{"PCMD", "POS", {0, 1, 4, 9}}, {"PFB", "POS", {0, 1, 3, 8}}};
    const CaptureMath fe = evaluate(c, {.op = MathOp::FollowingError, .a = "PCMD", .b = "PFB", .name = "PE"});
    ASSERT_TRUE(fe.ok());
    EXPECT_EQ(fe.channel.name, "PE");
    EXPECT_EQ(fe.channel.values, (std::vector<double>{0, 0, 1, 1}));
    const CaptureMath v = evaluate(c, {.op = MathOp::Derivative, .a = "PCMD"});
    ASSERT_TRUE(v.ok());
    EXPECT_EQ(v.channel.unit, "POS/s");
    EXPECT_DOUBLE_EQ(v.channel.values[1], (4.0 - 0.0) / (2 * 0.5)); // central difference over the capture's interval
    const CaptureMath missing = evaluate(c, {.op = MathOp::Sum, .a = "PCMD", .b = "VFB"});
    EXPECT_EQ(missing.status, MathStatus::UnknownChannel);
    EXPECT_NE(missing.error.find("VFB"), std::string::npos);
}

TEST(MathTrace, DerivativeAndIntegralAtUnevenTimes) {
    // y = a t + b at random, uneven times: d/dt is a exactly; the integral is a t^2 / 2 + b t from t0,
    // exact for a straight line under the trapezoid rule.
    std::mt19937 random(7);
    std::uniform_real_distribution<double> step(0.05, 0.15);
    const double a = -3.0, b = 2.0;
    Channel y{"VFB", "rpm", {}};
    double t = 1.0;
    for (int i = 0; i < 200; ++i, t += step(random)) y.samples.push_back({t, a * t + b});
    const TraceMath d = derivative(y);
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(d.channel.unit, "rpm/s");
    ASSERT_EQ(d.channel.samples.size(), y.samples.size());
    for (std::size_t i = 0; i < y.samples.size(); ++i) {
        EXPECT_DOUBLE_EQ(d.channel.samples[i].time_s, y.samples[i].time_s);
        ASSERT_NEAR(d.channel.samples[i].value, a, 1e-9);
    }
    const TraceMath in = integral(y);
    ASSERT_TRUE(in.ok());
    EXPECT_EQ(in.channel.unit, "rpm·s");
    const double t0 = y.samples.front().time_s;
    for (const Sample& s : in.channel.samples) {
        const double expected = a * (s.time_s * s.time_s - t0 * t0) / 2 + b * (s.time_s - t0);
        ASSERT_NEAR(s.value, expected, 1e-9);
    }
}

TEST(MathTrace, SecondOperandIsInterpolatedAtTheFirstsTimes) {
    // B = 2 t + 1 sampled at 0.05, 0.15, ...: linear, so interpolation is exact; A's samples before B's
    // first time and after its last are left out.
    Channel a{"VCMD", "rpm", {}}, b{"VFB", "rpm", {}};
    for (int i = 0; i <= 10; ++i) a.samples.push_back({0.1 * i, 10.0});
    for (int i = 0; i < 8; ++i) b.samples.push_back({0.05 + 0.1 * i, 2 * (0.05 + 0.1 * i) + 1});
    const TraceMath fe = followingError(a, b);
    ASSERT_TRUE(fe.ok()) << fe.error;
    ASSERT_EQ(fe.channel.samples.size(), 7u); // t = 0.1 .. 0.7
    for (const Sample& s : fe.channel.samples) EXPECT_NEAR(s.value, 10 - (2 * s.time_s + 1), 1e-12);
    EXPECT_NEAR(fe.channel.samples.front().time_s, 0.1, 1e-12);

    const Channel late{"X", "rpm", {{5, 1}, {6, 1}}};
    EXPECT_EQ(sum(a, late).status, MathStatus::NoOverlap);
    EXPECT_EQ(sum(a, Channel{"I", "A", {{0, 1}}}).status, MathStatus::UnitMismatch);
}

TEST(MathTrace, MovingAverageAndScaleKeepTimes) {
    Channel c{"VFB", "rpm", {}};
    for (int i = 0; i < 10; ++i) c.samples.push_back({0.3 * i, double(i)});
    const TraceMath m = movingAverage(c, 3);
    ASSERT_TRUE(m.ok());
    EXPECT_DOUBLE_EQ(m.channel.samples[0].value, 0.0);
    EXPECT_DOUBLE_EQ(m.channel.samples[1].value, 0.5);
    for (std::size_t i = 2; i < 10; ++i) EXPECT_DOUBLE_EQ(m.channel.samples[i].value, double(i) - 1); // (i-2+i-1+i)/3
    const TraceMath k = scaled(c, 0.5);
    EXPECT_DOUBLE_EQ(k.channel.samples[9].value, 4.5);
    EXPECT_DOUBLE_EQ(k.channel.samples[9].time_s, 2.7);

    SeriesStore store;
    const auto i = store.addChannel("VFB", "rpm");
    for (const Sample& s : c.samples) store.append(i, s);
    const TraceMath e = evaluate(store, {.op = MathOp::Integral, .a = "VFB"});
    ASSERT_TRUE(e.ok());
    EXPECT_NEAR(e.channel.samples.back().value, 0.5 * 9 * 2.7, 1e-9); // ramp 0..9 over 2.7 s
}
