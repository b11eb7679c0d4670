// The velocity loop's other modes and monitors, measured on a Bds5Servo the way an engineer would: the
// proportional loop (PROP, KPROP) — its bandwidth and its droop under load scale with KPROP; the two-pole
// current-command filter (LPF, LPFHZ) — its -3 dB point and the phase it costs the closed loop; VAVG as the
// 16 ms average of VFB; PRD as the raw resolver reading under PFB.
#include "bds5_test_drive.h"

#include "drive_core/bds5/bds5_servo.h"
#include "drive_core/bds5/bds5_variable_store.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <deque>
#include <functional>
#include <numbers>
#include <numeric>

using drive_core::bds5::Bds5Servo;
using drive_core::bds5::Bds5VariableStore;
namespace cat = drive_core::catalog::bds5;
using namespace std::chrono_literals;

namespace {
constexpr double kCountsPerRad = 4096 / (2 * std::numbers::pi);
constexpr double kBasicPerCps = 65.536;

double basic(const Bds5VariableStore& vars, const char* name) {
    return vars.read(*cat::findVariable(name));
}

// The response of `output` to a sine of amp_cps on the velocity command at f_Hz (after 0.3 s of settling,
// the fundamental over whole cycles), as a complex ratio: its magnitude the gain, its angle the phase.
std::complex<double> response(Bds5VariableStore& vars, double f_Hz, double amp_cps,
                              const std::function<double(const Bds5Servo&, const Bds5VariableStore&)>& output) {
    Bds5Servo servo;
    const double period_ms = 1000 / f_Hz;
    const int start = int(std::ceil(0.3 * f_Hz) * period_ms);
    const int end = start + int((std::ceil(0.5 * f_Hz) + 2) * period_ms);
    std::complex<double> y, x;
    for (int k = 0; k < end; ++k) {
        const double phase = 2 * std::numbers::pi * f_Hz * k * 1e-3;
        const double command = amp_cps * std::sin(phase);
        servo.tick(0, command, true, vars);
        if (k < start) continue;
        const double out = output(servo, vars);
        y += std::complex<double>(out * std::sin(phase), out * std::cos(phase));
        x += std::complex<double>(command * std::sin(phase), command * std::cos(phase));
    }
    return y / x;
}

double vfb(const Bds5Servo& servo, const Bds5VariableStore&) {
    return servo.velocity_cps();
}

// The -3 dB frequency of a response, by bisection.
double bandwidth_Hz(const std::function<double(double)>& gainAt) {
    double lo = 0.5, hi = 400;
    for (int i = 0; i < 30; ++i) {
        const double mid = std::sqrt(lo * hi);
        (gainAt(mid) > std::sqrt(0.5) ? lo : hi) = mid;
    }
    return lo;
}

Bds5VariableStore velocityLoop(bool prop, int kprop) {
    Bds5VariableStore vars;
    vars.set("PL", 0);
    vars.set("PROP", prop ? 1 : 0);
    vars.set("KPROP", kprop);
    return vars;
}

// Shaft torque per unit of current command (a fraction of IMAX) over the inertia: rad/s² per unit.
double torquePerInertia(const Bds5Servo& servo) {
    const auto& m = servo.plant().motor();
    return m.torqueConstant_NmPerA * m.peakCurrent_A / (m.rotorInertia_kgm2 + servo.plant().load().inertia_kgm2);
}
} // namespace

// PROP (L2072-2074): ICMD = KPROP x VE, on a rigid load a first-order loop a / s with a = KPROP' Kt Ipeak
// / J, closed through the 1 ms servo period's delay: the -3 dB point follows KPROP as that model says
// (about 2x per 2x KPROP while a is well below 1 / 1 ms, more as the delay begins to tell).
TEST(Bds5LoopModes, PropBandwidthFollowsKprop) {
    const Bds5Servo reference;
    constexpr double kDelay_s = 1e-3;
    for (const int kprop : {300, 600, 1200}) {
        Bds5VariableStore vars = velocityLoop(true, kprop);
        const double measured = bandwidth_Hz([&](double f) { return std::abs(response(vars, f, 60000, vfb)); });
        const double a = kprop * 5e-6 * torquePerInertia(reference);
        const double predicted = bandwidth_Hz([&](double f) {
            const std::complex<double> s(0, 2 * std::numbers::pi * f);
            const std::complex<double> loop = a * std::exp(-s * kDelay_s) / s;
            return std::abs(loop / (1.0 + loop));
        });
        std::printf("PROP KPROP %d: -3 dB at %.2f Hz (a / s with 1 ms delay: %.2f Hz, without: %.2f Hz)\n", kprop,
                    measured, predicted, a / (2 * std::numbers::pi));
        EXPECT_NEAR(measured, predicted, 0.06 * predicted) << "KPROP " << kprop;
    }
}

// A proportional loop holds a load torque with a speed error (droop) of T / (KPROP' Kt Ipeak); the
// integrating loop (PROP off) holds it with none.
TEST(Bds5LoopModes, PropDroopsUnderLoadInProportionToOneOverKprop) {
    const double command_cps = 1000 * 4096 / 60.0; // 1000 RPM
    const auto droop = [&](bool prop, int kprop) {
        Bds5VariableStore vars = velocityLoop(prop, kprop);
        Bds5Servo servo;
        drive_core::physics::LoadParameters load;
        load.externalTorque_Nm = 0.4;
        servo.setLoad(load);
        double sum = 0;
        for (int k = 0; k < 3000; ++k) {
            servo.tick(0, command_cps, true, vars);
            if (k >= 2000) sum += servo.velocity_cps();
        }
        return command_cps - sum / 1000;
    };
    const Bds5Servo reference;
    const auto& motor = reference.plant().motor();
    for (const int kprop : {500, 1000}) {
        const double d = droop(true, kprop);
        const double speed_rad = (command_cps - d) / kCountsPerRad;
        const double torque = 0.4 + motor.coulombFriction_Nm + motor.viscousFriction_NmPerRadPerS * speed_rad;
        const double predicted =
            torque / (kprop * 5e-6 * motor.torqueConstant_NmPerA * motor.peakCurrent_A) * kCountsPerRad;
        EXPECT_NEAR(d, predicted, 0.03 * predicted) << "KPROP " << kprop;
    }
    EXPECT_NEAR(droop(true, 500) / droop(true, 1000), 2, 0.1);
    EXPECT_LT(std::abs(droop(false, 0)), 0.005 * command_cps) << "the integrating loop has no droop";
}

// LPF (L6475-6481): two cascaded poles at LPFHZ on the current command. In torque mode (TQ: ICMD = KPROP
// x VCMD, no feedback) ICMD / VCMD is the filter alone: -3 dB at sqrt(sqrt(2) - 1) LPFHZ = 0.64 LPFHZ.
TEST(Bds5LoopModes, LpfIsTwoPolesAtLpfhz) {
    double lastBandwidth = 0;
    for (const int hz : {40, 80, 160, 250}) {
        Bds5VariableStore vars;
        vars.set("TQ", 1);
        vars.set("PL", 0);
        vars.set("KPROP", 1000);
        vars.set("LPF", 1);
        vars.set("LPFHZ", hz);
        const double flat = std::abs(
            response(vars, 1, 40000, [](const Bds5Servo&, const Bds5VariableStore& v) { return basic(v, "ICMD"); }));
        const auto gainAt = [&](double f) {
            return std::abs(response(vars, f, 40000,
                                     [](const Bds5Servo&, const Bds5VariableStore& v) { return basic(v, "ICMD"); })) /
                   flat;
        };
        const double measured = bandwidth_Hz(gainAt);
        std::printf("LPF LPFHZ %d: ICMD/VCMD -3 dB at %.2f Hz (two poles: %.2f Hz)\n", hz, measured, 0.6436 * hz);
        // The continuous cascade's -3 dB point; the sampled poles fall off faster well above it.
        if (hz <= 100) {
            EXPECT_NEAR(measured, 0.6436 * hz, 0.02 * 0.6436 * hz);
        }
        EXPECT_GT(measured, lastBandwidth * 1.4);
        lastBandwidth = measured;
        EXPECT_NEAR(gainAt(hz), 0.5, 0.01) << "each pole is 3 dB down at LPFHZ";
        vars.set("LPF", 0);
        EXPECT_NEAR(gainAt(hz), 1, 0.01) << "LPF off: no filter";
    }
}

// The filter's phase lag shows in the closed velocity loop as lost damping: a velocity step overshoots
// more with LPF on, the more the lower LPFHZ is ("LPFHZ should be set as high as possible, since it
// degrades the system performance", L6475).
TEST(Bds5LoopModes, LpfCostsTheVelocityLoopDamping) {
    const auto overshoot = [](int lpfhz) {
        Bds5VariableStore vars = velocityLoop(false, 0);
        vars.set("LPF", lpfhz > 0 ? 1 : 0);
        vars.set("LPFHZ", std::max(lpfhz, 1));
        Bds5Servo servo;
        double highest = 0;
        for (int k = 0; k < 1000; ++k) {
            servo.tick(0, 20000, true, vars);
            highest = std::max(highest, servo.velocity_cps());
        }
        return highest / 20000 - 1;
    };
    // Off and LPFHZ 250 leave the power-up loop (20 Hz, critically damped) without overshoot; lower
    // break frequencies make it ring more and more.
    const double off = overshoot(0), at250 = overshoot(250), at120 = overshoot(120), at80 = overshoot(80),
                 at60 = overshoot(60);
    std::printf("velocity step overshoot: LPF off %.1f %%, LPFHZ 250 %.1f %%, 120 %.1f %%, 80 %.1f %%, 60 %.1f %%\n",
                off * 100, at250 * 100, at120 * 100, at80 * 100, at60 * 100);
    EXPECT_LT(off, 0.005);
    EXPECT_LT(at250, 0.01);
    EXPECT_GT(at120, at250 + 0.003);
    EXPECT_GT(at80, at120 + 0.05);
    EXPECT_GT(at60, at80 + 0.05);
}

namespace {
// A variable in basic units as the whole drive holds it now.
double held(const bds5_test::TestDrive& t, const char* name) {
    return basic(t.drive.state().variables, name);
}
} // namespace

// VAVG (L2042): "averaged VFB over the previous 16 milliseconds" — the mean of the last 16 VFB samples, so
// it trails VFB while the motor speeds up and meets it at constant speed.
TEST(Bds5LoopModes, VavgIsTheMeanOfTheLastSixteenVfb) {
    bds5_test::TestDrive t;
    t.type("PLIM OFF\r");
    t.type("EN\r");
    t.type("ACC=5000\r"); // RPM/s
    t.type("J 1000\r");
    std::deque<double> last16;
    int compared = 0, trailing = 0;
    for (int ms = 0; ms < 400; ++ms) {
        t.drive.step(std::chrono::milliseconds(1));
        last16.push_back(held(t, "VFB"));
        if (last16.size() > 16) last16.pop_front();
        if (last16.size() < 16) continue;
        const double mean = std::accumulate(last16.begin(), last16.end(), 0.0) / 16;
        EXPECT_NEAR(held(t, "VAVG"), mean, 1.0) << ms << " ms"; // each value rounded to a basic unit
        ++compared;
        // While the speed climbs VAVG trails VFB (by 7.5 ms of acceleration, at least 10 RPM here).
        if (ms > 30 && ms < 150) {
            const double behind_rpm = (held(t, "VFB") - held(t, "VAVG")) * 10 / 44739;
            EXPECT_GT(behind_rpm, 10) << ms << " ms";
            ++trailing;
        }
    }
    EXPECT_GT(trailing, 50);
    EXPECT_NEAR(held(t, "VAVG"), held(t, "VFB"), 0.002 * held(t, "VFB")) << "at 1000 RPM they agree";
    EXPECT_EQ(compared, 385);
}

// PRD (L1997-2014): the raw R/D reading, 0-4095, under PFB. PRD is not latched: it reads the shaft as it
// is now, while PFB holds the sample taken at the start of the servo period, so during a move PRD is
// always the next period's PFB (mod 4096), and at rest the two agree. NORM moves PFB, not PRD; position
// units scale PFB, not PRD.
TEST(Bds5LoopModes, PrdIsTheResolverReadingUnderPfb) {
    bds5_test::TestDrive t;
    t.type("PLIM OFF\r");
    t.type("EN\r");
    EXPECT_EQ(held(t, "PRD"), held(t, "PFB"));
    t.type("MI 10000 500\r");
    int mismatches = 0;
    std::int64_t prdBefore = std::int64_t(held(t, "PRD"));
    for (int ms = 0; ms < 1000; ++ms) {
        t.drive.step(std::chrono::milliseconds(1));
        const auto pfb = std::int64_t(held(t, "PFB")), prd = std::int64_t(held(t, "PRD"));
        if (prd < 0 || prd > 4095 || ((pfb % 4096) + 4096) % 4096 != prdBefore) ++mismatches;
        prdBefore = prd;
    }
    t.drive.takeTransmitted();
    EXPECT_EQ(mismatches, 0);
    ASSERT_EQ(held(t, "PFB"), 10000);
    EXPECT_EQ(held(t, "PRD"), 10000 - 2 * 4096);
    t.type("PFB=0\r"); // NORM
    t.wait(5ms);
    EXPECT_EQ(held(t, "PFB"), 0);
    EXPECT_EQ(held(t, "PRD"), 1808) << "the resolver has not moved";
    t.type("PNUM=4096\r"); // degrees
    t.type("PDEN=360\r");
    t.type("MI 90 500\r");
    t.wait(1000ms);
    EXPECT_EQ(t.drive.state().variables.read("PFB").value_or(0), 90);
    EXPECT_EQ(t.drive.state().variables.read("PRD").value_or(0), 1808 + 1024) << "PRD stays in counts";
}
