// Feed to positive stop (SP bit 7, SF, ST; L1655-1688): a motion into a hard stop on the bench holds torque
// there instead of tripping #E1, SS shows FPS, and a stop command ends it with the position corrected.
#include "pmc960_test_drive.h"

namespace pmc960_test {
namespace {

TEST(Pmc960Fps, AMotionIntoAStopHoldsThereWithFpsSet) {
    TestDrive t;
    t.enable();
    t.drive.state().motion.setPositiveStop(1000.0); // a hard stop 1,000 counts ahead
    EXPECT_EQ(t.type("SP80\r"), prompted("SP80"));
    EXPECT_EQ(t.type("SF2048\r"), prompted("SF2048"));
    EXPECT_EQ(t.type("ST500\r"), prompted("ST500"));
    EXPECT_EQ(t.type("I5000+\r", 300ms), prompted("I5000+")); // commanded well past the stop: no #E1
    EXPECT_EQ(t.type("SS?"), prompted("SS?C2"));              // DRVON FPS, no MOTION, forward
    EXPECT_EQ(t.type("SM?"), prompted("SM?2"));
    EXPECT_EQ(t.type("G!"), prompted("G!1000"));
    EXPECT_EQ(t.type("I100+"), prompted("I100+#B2")); // nothing moves in FPS until a stop command
    EXPECT_EQ(t.type("I*\r"), prompted("I*"));
    EXPECT_EQ(t.type("SS?"), prompted("SS?82"));
    EXPECT_EQ(t.type("SF!"), prompted("SF!0"));
    t.drive.state().motion.setPositiveStop(std::nullopt);
    EXPECT_EQ(t.type("I500-\r", 300ms), prompted("I500-")); // the absolute position was corrected
    EXPECT_EQ(t.type("G!"), prompted("G!500"));
}

TEST(Pmc960Fps, WithoutSpBit7AStopTripsE1) {
    TestDrive t;
    t.enable();
    t.drive.state().motion.setPositiveStop(1000.0);
    t.type("SF2048\r");
    EXPECT_EQ(t.type("I5000+\r", 300ms), prompted("I5000+") + "#E1" + std::string(kPrompt));
    EXPECT_EQ(t.type("SM?"), prompted("SM?0"));
    EXPECT_EQ(t.type("G!"), prompted("G!1000"));
}

} // namespace
} // namespace pmc960_test
