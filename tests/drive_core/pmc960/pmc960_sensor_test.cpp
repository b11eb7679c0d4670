// The SENSOR input (JM4) and the SP profile bits that use it (L1612-1631, L1476-1492): external start,
// external decel, adaptive depth, home to SENSOR, and the motion errors #B1 and #B4.
#include "pmc960_test_drive.h"

#include <cmath>
#include <cstdlib>
#include <string>

namespace pmc960_test {
namespace {

using drive_core::pmc960::Pmc960Line;

// Factory units: V400 = 40,000 counts/s, A4000 = 4,000,000 counts/s² (10 ms to speed).
bool moving(TestDrive& t) {
    return t.drive.state().motion.moving();
}
double position(TestDrive& t) {
    return t.drive.state().motion.commanded_counts();
}

TEST(Pmc960Sensor, ExternalStartHoldsAnIndexUntilSensor) { // SP bits 5+4
    TestDrive t;
    t.enable();
    EXPECT_EQ(t.type("SP30\r"), prompted("SP30"));
    EXPECT_EQ(t.type("I1000+\r", 200ms), prompted("I1000+"));
    EXPECT_EQ(t.type("G!"), prompted("G!0"));
    t.drive.setLine(Pmc960Line::Sensor, true);
    t.wait(200ms);
    EXPECT_EQ(t.type("G!"), prompted("G!1000"));
}

TEST(Pmc960Sensor, ExternalStartOnlyForMotionFromRest) {
    TestDrive t;
    t.enable();
    t.type("SP30\r");
    t.type("J+\r"); // held: waits for SENSOR
    t.drive.setLine(Pmc960Line::Sensor, true);
    t.drive.setLine(Pmc960Line::Sensor, false);
    t.wait(50ms);
    ASSERT_TRUE(t.drive.state().motion.jogging());
    t.type("J200+\r", 20ms); // a speed change of a running jog starts at once
    EXPECT_EQ(t.type("J!"), prompted("J!200"));
}

TEST(Pmc960Sensor, AStopCancelsAStartStillWaitingForSensor) {
    TestDrive t;
    t.enable();
    t.type("SP30\r");
    t.type("I1000+\r", 50ms);
    EXPECT_EQ(t.type("I*\r", 20ms), prompted("I*"));
    EXPECT_FALSE(moving(t));
    t.drive.setLine(Pmc960Line::Sensor, true);
    t.wait(100ms);
    EXPECT_EQ(t.type("G!"), prompted("G!0"));
}

TEST(Pmc960Sensor, ExternalDecelRunsPastTheIndexUntilSensor) { // SP bit 3
    TestDrive t;
    t.enable();
    t.type("SP8\r");
    t.type("I1000+\r", 200ms);
    EXPECT_TRUE(moving(t)); // the calculated decel point is ignored
    EXPECT_GT(position(t), 5000);
    t.drive.setLine(Pmc960Line::Sensor, true);
    const double atSensor = position(t);
    t.wait(100ms);
    EXPECT_FALSE(moving(t));
    EXPECT_NEAR(position(t) - atSensor, 200, 1); // v²/2a at the A rate
}

TEST(Pmc960Sensor, ExternalDecelIgnoresSensorBeforeTopSpeed) {
    TestDrive t;
    t.enable();
    t.type("SP8\r");
    t.type("I1000+\r", 2ms); // still accelerating
    t.drive.setLine(Pmc960Line::Sensor, true);
    t.drive.setLine(Pmc960Line::Sensor, false);
    t.wait(100ms);
    EXPECT_TRUE(moving(t));
    t.drive.setLine(Pmc960Line::Sensor, true);
    t.wait(100ms);
    EXPECT_FALSE(moving(t));
}

TEST(Pmc960Sensor, AdaptiveDepthStopsSdCountsPastSensor) { // SP bit 6 with SD (L1476-1492)
    TestDrive t;
    t.enable();
    t.type("SP40\r");
    t.type("SD5000\r");
    t.type("I1000000+\r", 100ms);
    t.drive.setLine(Pmc960Line::Sensor, true);
    const double atSensor = position(t);
    t.wait(500ms);
    EXPECT_FALSE(moving(t));
    EXPECT_DOUBLE_EQ(position(t), atSensor + 5000);
}

TEST(Pmc960Sensor, AdaptiveDepthTooSmallIsB1) {
    TestDrive t;
    t.enable();
    // The following error at V400 as the loops make it: jog there and read the PSJ.
    t.type("J400+\r", 500ms);
    const std::string psj = t.type("SF!");
    const long error = std::strtol(psj.c_str() + 3, nullptr, 10);
    ASSERT_GT(error, 0);
    t.type("J*\r", 200ms);
    t.type("SP40\r");
    const long stop = 200; // counts to stop from V400 at A4000
    t.type("SD" + std::to_string(stop + error - 20) + "\r");
    EXPECT_EQ(t.type("I1000+"), "I1000+#B1" + std::string(kPrompt));
    EXPECT_FALSE(moving(t));
    t.type("SD" + std::to_string(stop + error + 20) + "\r");
    EXPECT_EQ(t.type("I1000+\r"), prompted("I1000+"));
}

TEST(Pmc960Sensor, AdaptiveDepthWithExternalDecelIsB4) {
    TestDrive t;
    t.enable();
    t.type("SP48\r");
    t.type("SD5000\r");
    EXPECT_EQ(t.type("G5000+"), "G5000+#B4" + std::string(kPrompt));
    EXPECT_FALSE(moving(t));
}

TEST(Pmc960Sensor, HomeStopsOnSensorWithStopSelect) { // SP bit 2: SENSOR, not the marker, ends H
    TestDrive t;
    t.enable();
    t.type("SP4\r");
    t.type("H+\r", 2500ms); // TUH: 2,000 counts/s
    EXPECT_TRUE(moving(t));
    EXPECT_GT(position(t), 4096); // passed the encoder marker
    t.drive.setLine(Pmc960Line::Sensor, true);
    t.wait(100ms);
    EXPECT_FALSE(moving(t));
    t.drive.setLine(Pmc960Line::Sensor, false);
    t.type("SP0\r");
    const double there = position(t);
    t.type("H+\r", 2500ms); // the marker again
    EXPECT_FALSE(moving(t));
    EXPECT_EQ(std::fmod(position(t), 4096.0), 0);
    EXPECT_GT(position(t), there);
}

} // namespace
} // namespace pmc960_test
