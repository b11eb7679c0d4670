// Rotary mode (ROTARY, PROTARY, L5248-5286): PFB, PCMD and PFNL roll over by PROTARY when PFB leaves
// 0..PROTARY, moves carry on through the roll-over, and a PROTARY that is a fraction of a count in user
// units accumulates no error however many turns the axis makes.
#include "bds5_test_drive.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace bds5_test;

namespace {
int value(TestDrive& t, const std::string& name) {
    const std::string out = t.type("P " + name + "\r");
    const auto start = out.find_first_not_of(' ', out.find("\r\n") + 2);
    return std::stoi(out.substr(start, out.find("\r\n", start) - start));
}

// The variable in user units as the drive holds it this millisecond.
int now(const TestDrive& t, const char* name) {
    return t.drive.state().variables.read(name).value_or(-999999);
}

double shaftRevolutions(const TestDrive& t) {
    return t.drive.state().servo.plant().motorAngle_rad() / (2 * std::numbers::pi);
}

// Runs until the move is over and the motor has settled, checking PFB every millisecond.
void runMove(TestDrive& t, int protary, int maxMs, int& outside, int& rollovers) {
    int last = now(t, "PFB");
    for (int ms = 0; ms < maxMs; ++ms) {
        t.drive.step(std::chrono::milliseconds(1));
        const int pfb = now(t, "PFB");
        if (pfb < 0 || pfb > protary) ++outside;
        if (std::abs(pfb - last) > protary / 2) ++rollovers;
        last = pfb;
    }
    t.drive.takeTransmitted();
}
} // namespace

TEST(Bds5Rotary, IncrementalMovesRollOverAndLandInsideProtary) {
    TestDrive t;
    t.type("PLIM OFF\r");
    EXPECT_EQ(value(t, "PROTARY"), 4096);
    t.type("ROTARY ON\r");
    t.type("EN\r");
    EXPECT_EQ(t.type("MI 41060 1000\r"), "MI 41060 1000\r\n-->") << "10 turns and 100 counts"; // L5284
    int outside = 0, rollovers = 0;
    runMove(t, 4096, 1500, outside, rollovers);
    EXPECT_EQ(outside, 0) << "PFB stays within 0..PROTARY every millisecond";
    EXPECT_EQ(rollovers, 10);
    EXPECT_EQ(value(t, "PFB"), 100);
    EXPECT_EQ(value(t, "PCMD"), 100);
    EXPECT_EQ(value(t, "PFNL"), 100);
    EXPECT_NEAR(shaftRevolutions(t), 41060.0 / 4096, 1.0 / 4096) << "the shaft really turned ten times";

    // Backwards: below 0 the positions go up by PROTARY.
    t.type("MI -12338 1000\r"); // 3 turns and 50 counts back from 100
    runMove(t, 4096, 1000, outside, rollovers);
    EXPECT_EQ(outside, 0);
    EXPECT_EQ(value(t, "PFB"), 4096 + 100 - 12338 + 2 * 4096);
    EXPECT_EQ(value(t, "PFNL"), value(t, "PFB"));
    EXPECT_EQ(value(t, "PCMD"), value(t, "PFB"));
}

TEST(Bds5Rotary, AbsoluteMovesStayWithinTheTurn) { // L5280-5286
    TestDrive t;
    t.type("PLIM OFF\r");
    t.type("ROTARY ON\r");
    t.type("EN\r");
    t.type("MI 20000 1000\r");
    t.wait(1000ms);
    ASSERT_EQ(value(t, "PFB"), 20000 - 4 * 4096);
    EXPECT_NE(t.type("MA 4097\r").find("ERR 60"), std::string::npos);
    const double before = shaftRevolutions(t);
    t.type("MA 10 1000\r"); // the short way back within the turn, not back through the four turns
    t.wait(1000ms);
    EXPECT_EQ(value(t, "PFB"), 10);
    EXPECT_NEAR(shaftRevolutions(t) - before, (10.0 - 3616) / 4096, 1.0 / 4096);
}

TEST(Bds5Rotary, ProtaryExactInUserUnitsAccumulatesNoError) { // L5264-5278: a 5:3 gearbox, degrees
    TestDrive t;
    t.type("PLIM OFF\r");
    t.type("PNUM=20480\r");  // 4096 x 5
    t.type("PDEN=1080\r");   // 360 x 3
    t.type("PROTARY=360\r"); // 6826 2/3 counts
    t.type("ROTARY ON\r");
    t.type("EN\r");
    // 300 turns of the table and 90 degrees: 500 motor turns. Rounding PROTARY to 6827 counts would leave
    // the table 100 counts (5.3 degrees) short.
    t.type("MI 108090 3000\r");
    int outside = 0, rollovers = 0;
    runMove(t, 360, 12000, outside, rollovers);
    EXPECT_EQ(outside, 0);
    EXPECT_EQ(rollovers, 300);
    EXPECT_EQ(value(t, "PFB"), 90);
    EXPECT_EQ(value(t, "PCMD"), 90);
    EXPECT_EQ(value(t, "PFNL"), 90);
    EXPECT_NEAR(shaftRevolutions(t), 108090.0 * 5 / 3 / 360, 1.0 / 4096);
    // Once more round, to the same place.
    t.type("MI 360 3000\r");
    t.wait(1000ms);
    EXPECT_EQ(value(t, "PFB"), 90);
}

TEST(Bds5Rotary, UnitsAndProtaryAreFrozenWhileRotaryIsOn) { // L5258
    TestDrive t;
    t.type("ROTARY ON\r");
    for (const char* write : {"PROTARY=1000\r", "PNUM=2\r", "PDEN=2\r"})
        EXPECT_NE(t.type(write).find("ERR 59"), std::string::npos) << write;
    EXPECT_EQ(value(t, "PROTARY"), 4096);
    t.type("ROTARY OFF\r");
    t.type("PROTARY=1000\r");
    EXPECT_EQ(value(t, "PROTARY"), 1000);
}
