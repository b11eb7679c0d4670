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
