// The simulated SC750's servo faults (DECISIONS 56; FAULTCODE table L1522-L1588): overspeed (1), I.t (4) and
// following error overflow (F 1, 241) trip from the plant, disable the amplifier, latch, and clear when the
// enable is taken away. Asserted by relations: the I.t trip time is the first-order filter's (ITF0) time to
// reach IT.THRESH % of the controller's peak current at the current the motor really draws.
#include "sc750_bench.h"

#include "drive_core/catalog/sc750_catalog.h"
#include "drive_core/catalog/sc750_motors.h"
#include "drive_core/simulator_controls.h"

#include <cmath>
#include <numbers>

namespace sc750_test {
namespace {

namespace cat = drive_core::catalog::sc750;
constexpr drive_core::Microseconds kTick{427};
constexpr double kTick_s = 0.000427;

// An enabled drive with no program on the boiler-plate motor (R32G) and controller (MODEL 752).
struct Servo : ServoBench {
    using ServoBench::ServoBench;
    int fault() { return int(value("FAULTCODE")); }
    // Ticks until the drive shows a fault other than "enabled", at most `limit_s`; the time it took, or -1.
    double untilFault(double limit_s) {
        for (long i = 0, n = std::lround(limit_s / kTick_s); i < n; ++i) {
            if (fault() != cat::kFaultEnabled) return double(i) * kTick_s;
            b.drive.step(kTick);
        }
        return -1;
    }
    void run(double seconds) {
        for (long i = 0, n = std::lround(seconds / kTick_s); i < n; ++i) b.drive.step(kTick);
    }
};

double motorPeakTorque_Nm() {
    const cat::SetupData motor = cat::findMotor("R32G")->data;
    return motor.torqueConstant_NmPerA * motor.peak_A;
}

// BLKTYPE 0 (torque block, L1934): a constant current command with nothing closing a speed loop runs the
// motor away until the software overspeed trips; disabled, the motor then coasts.
TEST(Sc750ServoFault, OverspeedTripsARunawayAndTheMotorCoasts) {
    Servo s({{"BLKTYPE", "0"}, {"KVP", "1"}, {"KVI", "0"}});
    ASSERT_EQ(s.fault(), cat::kFaultEnabled);
    s.b.drive.controls()->setAnalogInput_V(1.0); // 2 A
    const double tripped = s.untilFault(20);
    ASSERT_GT(tripped, 0) << "RVEL " << s.value("RVEL");
    EXPECT_EQ(s.fault(), cat::kFaultOverspeed);
    EXPECT_GT(std::abs(s.value("RVEL")), 12000);
    EXPECT_EQ(s.value("ENABLED"), 0);
    const double atTrip = std::abs(s.value("RVEL"));
    s.run(0.2);
    EXPECT_LT(std::abs(s.value("RVEL")), atTrip); // no current: friction slows it
    EXPECT_EQ(s.value("ICMD"), 0);
}

// A stall at a steady current I above the threshold: IT.FILT = I (1 - exp(-2 pi ITF0 t)) reaches
// IT.THRESH % of the controller's peak at t = -ln(1 - threshold / I) / (2 pi ITF0); not before, and the
// same relation holds for another IT.THRESH.
TEST(Sc750ServoFault, ItTripsAStallWhenTheFilterReachesTheThreshold) {
    const double peak_A = cat::findControllerModel(752)->peak_A;
    for (const int threshold : {60, 40}) {
        Servo s({{"IT.THRESH", std::to_string(threshold)}});
        const double load_Nm = 0.85 * motorPeakTorque_Nm(); // held at rest against it
        s.b.drive.controls()->setLoadTorque_Nm(load_Nm);
        s.run(0.5);
        const double current_A = std::abs(s.value("IFB"));
        ASSERT_GT(current_A, threshold / 100.0 * peak_A) << "the stall must draw more than the threshold";
        const double expected_s =
            -std::log(1 - threshold / 100.0 * peak_A / current_A) / (2 * std::numbers::pi * s.value("ITF0")) - 0.5;
        const double tripped = s.untilFault(2 * expected_s);
        ASSERT_GT(tripped, 0) << "IT.FILT never reached IT.THRESH";
        EXPECT_NEAR(tripped, expected_s, 0.03 * expected_s + 0.05) << "IT.THRESH " << threshold;
        EXPECT_EQ(s.fault(), cat::kFaultIt);
        EXPECT_EQ(s.value("ENABLED"), 0);
    }
}

// A load beyond the motor's peak torque drags the shaft away from a held position; past the error register's
// range (8 revolutions) the drive shows F 1, disables, and keeps showing it until ENABLE is written 0, after
// which ENABLE=1 holds again where the shaft now is.
TEST(Sc750ServoFault, FollowingErrorOverflowLatchesUntilTheEnableIsReset) {
    Servo s;
    s.b.drive.controls()->setLoadTorque_Nm(1.2 * motorPeakTorque_Nm()); // slow enough to stay under overspeed
    const double tripped = s.untilFault(5);
    ASSERT_GT(tripped, 0);
    EXPECT_EQ(s.fault(), cat::kFaultFollowingError);
    EXPECT_GT(std::abs(s.value("POSITION")), 8 * 4096 - 100);
    EXPECT_EQ(s.value("ENABLED"), 0);
    s.b.drive.controls()->setLoadTorque_Nm(0);
    s.run(0.5);
    EXPECT_EQ(s.fault(), cat::kFaultFollowingError) << "latched";
    EXPECT_EQ(s.b.drive.writeNamed("ENABLE", "0"), "");
    s.run(0.01);
    EXPECT_EQ(s.fault(), cat::kFaultNone);
    EXPECT_EQ(s.b.drive.writeNamed("ENABLE", "1"), "");
    s.run(0.5);
    EXPECT_EQ(s.fault(), cat::kFaultEnabled);
    EXPECT_LT(std::abs(s.value("POS.ERROR")), 10);
}

} // namespace
} // namespace sc750_test
