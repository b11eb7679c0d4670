// The system modes SM0-SM3 (L212-223, L1577-1601): what the motor does and what the PSJ (SF!) holds in each,
// seen through G! (the motor's absolute position), SF! and SM?.
#include "pmc960_test_drive.h"

#include <cstdlib>
#include <string>

namespace pmc960_test {
namespace {

// The number in an answer such as "G!-123\r\n=}".
long answer(TestDrive& t, std::string_view display) {
    const std::string text = t.type(display);
    return std::strtol(text.c_str() + display.size(), nullptr, 10);
}

// The servo loops run on the simulated motor (pmc960_physics_test.cpp); J100 jogs at 10,000 counts/s.
// SM1: the motor's speed is the feedforward's share of the reference's, with no position loop: the distance
// it runs is proportional to FFGAIN (the share itself depends on the motor and tach, DECISIONS.md S4).
TEST(Pmc960Modes, VelocityModeRunsAtTheFeedforwardShareWithoutAPositionLoop) { // SM1
    auto velocityModeIndex = [](int feedForward) {
        TestDrive t;
        t.writeEnable();
        const std::string gain = "TGF" + std::to_string(feedForward);
        EXPECT_EQ(t.type(gain + "\r"), prompted(gain));
        EXPECT_EQ(t.type("SM1\r"), prompted("SM1"));
        EXPECT_EQ(t.type("I4096+\r", 500ms), prompted("I4096+"));
        EXPECT_EQ(t.type("SF!"), prompted("SF!0"));  // the reference is not summed in the PSJ
        EXPECT_EQ(t.type("SS?"), prompted("SS?82")); // DRVON, at rest, forward
        return answer(t, "G!");
    };
    const long half = velocityModeIndex(16), full = velocityModeIndex(32);
    EXPECT_NE(full, 4096);                               // no position loop: it does not land on the distance
    EXPECT_NEAR(double(full) / double(half), 2.0, 0.05); // twice FFGAIN, twice the speed

    TestDrive position;
    position.writeEnable();
    position.type("TGF64\r");
    position.enable();
    position.type("I4096+\r", 500ms);
    EXPECT_EQ(position.type("G!"), prompted("G!4096")); // SM2 closes the position loop: it lands
}

TEST(Pmc960Modes, VelocityModeNeverTripsOnFollowingError) { // SF trips only in a position mode (L221-223)
    TestDrive t;
    EXPECT_EQ(t.type("SM1\r"), prompted("SM1"));
    t.type("SF8\r");
    EXPECT_EQ(t.type("J+\r", 200ms), prompted("J+"));
    EXPECT_EQ(t.type("SM?"), prompted("SM?1"));
    EXPECT_EQ(t.type("SF!"), prompted("SF!0"));
    EXPECT_GT(answer(t, "G!"), 200); // 1/8 of 10,000 counts/s for 0.2 s, less the ramp
}

TEST(Pmc960Modes, IdleKeepsTheErrorAndSm2AtRestTakesItIntoTheAbsolutePosition) { // L1589-1590
    TestDrive t;
    t.enable();
    t.type("J+\r", 300ms);
    EXPECT_GT(answer(t, "SF!"), 0);              // the motor lags the reference
    EXPECT_EQ(t.type("SM0\r"), prompted("SM0")); // the reference stops; the disabled drive brakes the motor
    t.wait(50ms);
    EXPECT_GT(answer(t, "SF!"), 0); // the PSJ keeps the count
    const long motor = answer(t, "G!");
    t.wait(200ms);
    EXPECT_EQ(answer(t, "G!"), motor); // nothing moves in IDLE
    EXPECT_EQ(t.type("SM2\r", 200ms), prompted("SM2"));
    EXPECT_EQ(t.type("SF!"), prompted("SF!0"));
    EXPECT_EQ(answer(t, "G!"), motor); // no jump
    EXPECT_EQ(t.type("G+\r", 500ms), prompted("G+"));
    EXPECT_EQ(t.type("G!"), prompted("G!0")); // the absolute position was adjusted: zero is zero
}

TEST(Pmc960Modes, Sm3KeepsTheErrorAndTheMotorJumpsToCancelIt) { // L1592-1593
    TestDrive t;
    t.enable();
    t.type("J+\r", 300ms);
    t.type("SM0\r", 50ms);
    const long error = answer(t, "SF!");
    const long motor = answer(t, "G!");
    ASSERT_GT(error, 0);
    EXPECT_EQ(t.type("SM3\r", 500ms), prompted("SM3"));
    EXPECT_EQ(t.type("SF!"), prompted("SF!0"));
    EXPECT_NEAR(answer(t, "G!"), motor + error, 1); // where the reference stopped (each display rounded)
    t.type("G+\r", 500ms);
    EXPECT_EQ(t.type("G!"), prompted("G!0"));
}

TEST(Pmc960Modes, Sm2AfterAnOverflowClearsThePsjWithoutAdjustingThePosition) { // L1590, L1598-1599
    TestDrive t;
    t.enable();
    t.type("SF32\r"); // below the lag at J100
    t.type("J+\r");
    EXPECT_EQ(t.wait(50ms), "#E1" + std::string(kPrompt));
    const long error = answer(t, "SF!");
    EXPECT_GT(error, 0); // the count stays in the PSJ (less what the motor coasted as it was braked)
    EXPECT_EQ(t.type("SM2\r", 200ms), prompted("SM2"));
    EXPECT_EQ(t.type("SF!"), prompted("SF!0"));
    t.type("SF2048\r"); // room for the lag at V400
    EXPECT_EQ(t.type("G+\r", 500ms), prompted("G+"));
    EXPECT_EQ(answer(t, "G!"), -error); // zero is off by the cleared count: the position is lost
}

TEST(Pmc960Modes, Sm3DoesNotClearAnOverflow) { // E1: "SM0 then SM1 or SM2" (L2382)
    TestDrive t;
    t.enable();
    t.type("SF32\r"); // below the lag at J100
    t.type("J+\r");
    ASSERT_EQ(t.wait(50ms), "#E1" + std::string(kPrompt));
    const long motor = answer(t, "G!");
    EXPECT_EQ(t.type("SM3\r"), prompted("SM3"));
    EXPECT_EQ(t.wait(5ms), "#E1" + std::string(kPrompt));
    EXPECT_EQ(t.type("SM?"), prompted("SM?0"));
    EXPECT_EQ(answer(t, "G!"), motor); // no jump
    t.type("SM2\r", 5ms);
    EXPECT_EQ(t.type("SM?"), prompted("SM?2"));
}

} // namespace
} // namespace pmc960_test
