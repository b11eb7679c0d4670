// Faults and the enable chain on the simulated motor (seed-bds5 §6.4, §7.1-7.2, §7.17): PE overflow,
// over-speed, travel limits, REMOTE and MOTION, foldback — what the terminal shows and what the drive does.
#include "bds5_test_drive.h"

#include "drive_core/bds5/bds5_servo.h"

#include <gtest/gtest.h>

using namespace bds5_test;

namespace {
std::string value(TestDrive& t, const std::string& name) {
    const std::string out = t.type("P " + name + "\r");
    const auto start = out.find_first_not_of(' ', out.find("\r\n") + 2);
    return out.substr(start, out.find("\r\n", start) - start);
}
} // namespace

TEST(Bds5Faults, PeOverflowDisablesTheDrive) { // ERR 25, severity 3 (L7230)
    TestDrive t;
    t.type("PLIM OFF\r");
    t.type("PEMAX=100\r");
    t.type("EN\r");
    EXPECT_EQ(value(t, "ACTIVE"), "1");
    t.type("J 1000\r", 200ms);
    EXPECT_NE(t.type("\r").find("\aERR 25 PE OVERFLOW"), std::string::npos) << "KF 0: the error grows with speed";
    EXPECT_EQ(value(t, "ACTIVE"), "0");
    EXPECT_EQ(value(t, "READY"), "0");
    EXPECT_EQ(value(t, "FAULT"), "1");
    EXPECT_EQ(value(t, "PE"), "0") << "disabled: PCMD follows PFB";
    t.type("EN\r");
    EXPECT_EQ(value(t, "FAULT"), "0") << "EN resets the FAULT latch";
}

TEST(Bds5Faults, OverSpeedDisablesTheDrive) { // ERR 13 (L7195)
    TestDrive t;
    t.type("PLIM OFF\r");
    t.type("VOSPD=500\r"); // only while disabled
    t.type("EN\r");
    t.type("J 1000\r", 200ms);
    EXPECT_NE(t.type("\r").find("\aERR 13 OVER-SPEED"), std::string::npos);
    EXPECT_EQ(value(t, "ACTIVE"), "0");
}

TEST(Bds5Faults, HardwareLimitSwitchDisablesAndTheMotorCoasts) { // ERR 24 (L2245-2249)
    TestDrive t;
    t.type("PLIM OFF\r");
    t.type("EN\r");
    t.type("J 500\r", 300ms);
    t.drive.controls()->setLimitSwitches(true, false);
    t.wait(5ms);
    EXPECT_NE(t.type("\r").find("\aERR 24 HARDWARE OVERTRAVEL"), std::string::npos);
    EXPECT_EQ(value(t, "ACTIVE"), "0");
    EXPECT_EQ(value(t, "OK2EN"), "0");
    EXPECT_NE(value(t, "VFB"), "0") << "coasting, not braked";
    EXPECT_EQ(value(t, "ICMD"), "0");
    EXPECT_TRUE(t.drive.controls()->status().positiveLimit);
}

TEST(Bds5Faults, SoftwareLimitStopsButStaysEnabled) { // ERR 23, severity 2 (L2237-2259)
    TestDrive t;
    t.type("PMAX=2000\r");
    t.type("EN\r");
    t.type("J 100\r", 1000ms);
    EXPECT_NE(t.type("\r").find("\aERR 23 SOFTWARE OVERTRAVEL"), std::string::npos);
    t.wait(300ms);
    EXPECT_EQ(value(t, "VCMD"), "0");
    EXPECT_EQ(value(t, "ACTIVE"), "1");
}

// One software overtravel is one error (L2255, L7214): shown once and logged once in ERR HIST, however many
// servo periods the stop at AMAX spends outside PMAX. A new command outward is a new overtravel.
TEST(Bds5Faults, SoftwareOvertravelIsLoggedOncePerEvent) {
    TestDrive t;
    t.type("PMAX=2000\r");
    t.type("EN\r");
    t.type("J 1000\r", 500ms); // 1000 RPM: PFB passes 2000 counts within 0.1 s; the stop at AMAX takes 10 ms
    const std::string shown = t.type("\r");
    EXPECT_EQ(count(shown, "ERR 23 SOFTWARE OVERTRAVEL"), 1) << shown;
    EXPECT_EQ(count(t.type("ERR HIST\r"), "ERR 23 SOFTWARE OVERTRAVEL"), 1);
    EXPECT_EQ(value(t, "VCMD"), "0");
    t.type("J 100\r", 300ms); // outward again from beyond PMAX (L2255: no positive motion)
    EXPECT_EQ(count(t.type("\r"), "ERR 23 SOFTWARE OVERTRAVEL"), 1);
    const std::string history = t.type("ERR HIST\r");
    EXPECT_EQ(count(history, "ERR 23 SOFTWARE OVERTRAVEL"), 2) << history;
    t.type("J -100\r", 300ms); // inward is allowed
    EXPECT_EQ(t.type("\r"), "\r\n-->");
    EXPECT_NE(value(t, "VCMD"), "0");
}

TEST(Bds5Faults, RemoteOffLeavesReadyButNotActive) { // Area 5: ACTIVE = READY and REMOTE
    TestDrive t;
    t.type("EN\r");
    t.drive.controls()->setEnableInput(false);
    t.wait(2ms);
    EXPECT_EQ(value(t, "READY"), "1");
    EXPECT_EQ(value(t, "ACTIVE"), "0");
    EXPECT_FALSE(t.drive.controls()->status().active);
    t.drive.controls()->setEnableInput(true);
    t.wait(2ms);
    EXPECT_EQ(value(t, "ACTIVE"), "1");
    EXPECT_TRUE(t.drive.controls()->status().active);
}

TEST(Bds5Faults, MotionInputDroppingStopsTheMove) { // ERR 19 (L2196-2210)
    TestDrive t;
    t.type("PLIM OFF\r");
    t.type("EN\r");
    t.type("J 500\r", 200ms);
    t.drive.controls()->setMotionInput(false);
    t.wait(50ms);
    EXPECT_NE(t.type("\r").find("\aERR 19"), std::string::npos);
    EXPECT_EQ(value(t, "VCMD"), "0") << "stopped at AMAX";
    EXPECT_EQ(value(t, "ACTIVE"), "1") << "severity 2: still enabled";
}

TEST(Bds5Faults, DisabledCommandFollowsAShaftTurnedByHand) { // L2115, L2038: VFB is live when disabled
    TestDrive t;
    t.drive.controls()->setLoadTorque_Nm(-0.2);
    t.wait(300ms);
    const std::string pfb = value(t, "PFB");
    EXPECT_NE(pfb, "0");
    const std::string both = value(t, "PCMD PFB"); // one line: the same instant
    EXPECT_EQ(both.substr(0, both.find(' ')), both.substr(both.find_last_of(' ') + 1)) << both;
    EXPECT_EQ(value(t, "PE"), "0");
    EXPECT_NE(value(t, "VFB"), "0");
}

TEST(Bds5Faults, ActiveDriveHoldsAgainstALoadTorque) { // the integrating loop: no steady-state error
    TestDrive t;
    t.type("EN\r");
    t.drive.controls()->setLoadTorque_Nm(1.0);
    t.wait(1000ms);
    EXPECT_EQ(value(t, "PFB"), "0");
    EXPECT_NE(value(t, "ICMD"), "0") << "the current holding the load";
}

// Foldback (L2143-2168): at full current IFOLD falls from well above IMAX to IMAX in 2-3 s, then to ICONT
// in about 10 s more; FOLD and SAT come on. A locked rotor: an inertia too large to move.
TEST(Bds5Faults, FoldbackFollowsTheManualsTimeScales) {
    drive_core::bds5::Bds5VariableStore vars;
    drive_core::bds5::Bds5Servo servo;
    drive_core::physics::LoadParameters locked;
    locked.inertia_kgm2 = 1e4;
    servo.setLoad(locked);
    vars.set("TQ", 1);
    vars.set("PL", 0);
    int reachedImax_ms = -1;
    for (int ms = 0; ms < 20000; ++ms) {
        servo.tick(0, 1e6, true, vars); // torque mode, a command far above ILIM
        if (reachedImax_ms < 0 && vars.read("IFOLD").value_or(0) <= 100) reachedImax_ms = ms;
    }
    EXPECT_GE(reachedImax_ms, 2000);
    EXPECT_LE(reachedImax_ms, 3500);
    const int icont = vars.read("ICONT").value_or(0);
    EXPECT_NEAR(vars.read("IFOLD").value_or(0), icont, 0.03 * 100) << "IFOLD settles at ICONT";
    EXPECT_NEAR(vars.read("IMON").value_or(0), icont, 0.03 * 100);
    EXPECT_EQ(vars.read("FOLD").value_or(0), 1);
    EXPECT_EQ(vars.read("SAT").value_or(0), 1);
}
