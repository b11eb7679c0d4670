// The electronic gearbox from the simulated master encoder (L2923-3042): the ratio with its fraction
// carried, MI summed onto the geared command, the motor following, and ERR 97 above 2 MHz.
#include "bds5_test_drive.h"

#include "drive_core/simulator_controls.h"

#include <gtest/gtest.h>

using namespace bds5_test;

namespace {
std::string value(TestDrive& t, const std::string& name) {
    const std::string out = t.type("P " + name + "\r");
    const auto start = out.find_first_not_of(' ', out.find("\r\n") + 2);
    return out.substr(start, out.find("\r\n", start) - start);
}

// Master pulses for exactly `ms` milliseconds, then none.
void master(TestDrive& t, double hz, int ms) {
    t.drive.controls()->setMasterFrequency_Hz(hz);
    for (int i = 0; i < ms; ++i) t.drive.step(std::chrono::milliseconds(1));
    t.drive.controls()->setMasterFrequency_Hz(0);
    t.drive.takeTransmitted();
}
} // namespace

TEST(Bds5Gearbox, FollowsTheMasterAtGeariOverGearo) {
    TestDrive t;
    t.type("PLIM OFF\r");
    t.type("GEARI=4096\r"); // a 500-line encoder (2000 counts a rev) geared 1:3 (L2975)
    t.type("GEARO=6000\r");
    t.type("EN\r");
    t.type("GEAR ON\r");
    const int pcmd0 = std::stoi(value(t, "PCMD"));
    master(t, 6000, 1500); // 9000 master counts
    EXPECT_EQ(std::stoi(value(t, "PCMD")) - pcmd0, 6144) << "9000 x 4096 / 6000, no count lost";
    t.wait(500ms);
    EXPECT_EQ(value(t, "PFB"), value(t, "PCMD")) << "the motor has followed";
}

TEST(Bds5Gearbox, MiIsSummedOntoTheGearedCommand) { // L2994-3000: phase adjust
    TestDrive t;
    t.type("PLIM OFF\r");
    t.type("GEARI=1\r");
    t.type("GEARO=1\r");
    t.type("EN\r");
    t.type("GEAR ON\r");
    const int pcmd0 = std::stoi(value(t, "PCMD"));
    t.type("MI 1028 10\r");
    master(t, 2000, 1000);
    t.wait(1000ms);
    EXPECT_EQ(std::stoi(value(t, "PCMD")) - pcmd0, 2000 + 1028);
    EXPECT_NE(t.type("MA 0\r").find("\aERR 56"), std::string::npos) << "MA is not allowed with GEAR";
}

TEST(Bds5Gearbox, VoffDrivesTheCommandWithoutAMaster) { // L9520: VOFF 20 RPM ~ 1365 counts/s
    TestDrive t;
    t.type("PLIM OFF\r");
    t.type("EN\r");
    t.type("VOFF=20\r");
    t.type("GEAR ON\r");
    EXPECT_EQ(value(t, "VOFF"), "0") << "GEAR ON resets VOFF";
    t.type("VOFF=20\r");
    const int pcmd0 = std::stoi(value(t, "PCMD"));
    t.wait(2000ms); // and the time the P commands take on the wire
    EXPECT_NEAR(std::stoi(value(t, "PCMD")) - pcmd0, 2730, 80);
}

TEST(Bds5Gearbox, TooFastAMasterIsGearOverflow) { // ERR 97, severity 3 (L7449)
    TestDrive t;
    t.type("PLIM OFF\r");
    t.type("GEARI=32767\r");
    t.type("GEARO=1\r");
    t.type("EN\r");
    t.type("GEAR ON\r");
    master(t, 1000, 50); // 1 count a ms x 32767: 33 MHz
    EXPECT_NE(t.type("\r").find("\aERR 97 GEAR OVERFLOW"), std::string::npos);
    EXPECT_EQ(value(t, "ACTIVE"), "0");
}

namespace {
// VCMD in RPM (the power-up velocity units) as the drive holds it now.
double vcmdRpm(const TestDrive& t) {
    return t.drive.state().variables.read("VCMD").value_or(-1);
}
void runMs(TestDrive& t, int ms) {
    for (int i = 0; i < ms; ++i) t.drive.step(std::chrono::milliseconds(1));
    t.drive.takeTransmitted();
}
} // namespace

// RAMP (L3033-3042, L5599): run as a velocity loop (PL off), the gearbox's velocity command slews at ACC
// when it is engaged or the ratio raises the speed, and at DEC when the speed falls.
TEST(Bds5Gearbox, RampSlewsTheGearedVelocityAtAccAndDec) {
    TestDrive t;
    t.type("PLIM OFF\r");
    t.type("PL OFF\r");
    t.type("ACC=1000\r"); // RPM/s
    t.type("DEC=2000\r");
    t.type("GEARI=1\r");
    t.type("GEARO=1\r");
    t.type("RAMP ON\r");
    t.type("EN\r");
    t.drive.controls()->setMasterFrequency_Hz(40000); // 40 counts a ms: 585.9 RPM geared 1:1
    t.type("GEAR ON\r");
    const double geared = 40000 * 60.0 / 4096;
    const double v0 = vcmdRpm(t);
    EXPECT_LT(v0, 100) << "engaging does not jump to the master's speed";
    runMs(t, 200);
    EXPECT_NEAR(vcmdRpm(t) - v0, 200, 2) << "1000 RPM/s for 0.2 s";
    runMs(t, 600);
    EXPECT_NEAR(vcmdRpm(t), geared, 1) << "and then follows the master";
    EXPECT_NEAR(t.drive.state().variables.read("VFB").value_or(0), geared, 15) << "the motor with it";

    t.type("GEARO=2\r"); // half the speed: down at DEC
    const double v1 = vcmdRpm(t);
    EXPECT_GT(v1, geared / 2 + 100);
    runMs(t, 50);
    EXPECT_NEAR(v1 - vcmdRpm(t), 100, 2) << "2000 RPM/s for 50 ms";
    runMs(t, 200);
    EXPECT_NEAR(vcmdRpm(t), geared / 2, 1);

    t.type("RAMP OFF\r");
    t.type("GEARO=1\r");
    EXPECT_NEAR(vcmdRpm(t), geared, 1) << "without RAMP the command steps at once";

    t.type("RAMP ON\r");
    t.type("GEAR OFF\r"); // chosen: down to rest at DEC
    const double v2 = vcmdRpm(t);
    EXPECT_GT(v2, geared - 60);
    runMs(t, 100);
    EXPECT_NEAR(v2 - vcmdRpm(t), 200, 2);
    runMs(t, 300);
    EXPECT_EQ(vcmdRpm(t), 0);
}

TEST(Bds5Gearbox, RampDoesNothingWithThePositionLoopOn) { // "only when PL is off" (L5613)
    TestDrive t;
    t.type("PLIM OFF\r");
    t.type("GEARI=1\r");
    t.type("GEARO=1\r");
    t.type("RAMP ON\r");
    t.type("EN\r");
    t.drive.controls()->setMasterFrequency_Hz(40000);
    t.type("GEAR ON\r");
    EXPECT_NEAR(vcmdRpm(t), 40000 * 60.0 / 4096, 1);
    t.drive.controls()->setMasterFrequency_Hz(0);
}
