// The Cam command's errors (digest §7.1): each raised where its situation arises on the simulated PMC-960.
#include "pmc960_test_drive.h"

namespace pmc960_test {
namespace {

std::string refused(std::string_view echo, std::string_view code) {
    return std::string(echo) + "#" + std::string(code) + std::string(kPrompt);
}

TEST(Pmc960Cam, KeepingTheSpeedNeedsARunningCamIs81) {
    TestDrive t;
    t.enable();
    EXPECT_EQ(t.type("C1000\r"), refused("C1000", "81"));
    EXPECT_FALSE(t.drive.state().motion.moving());
}

// pmc960_drive_fuzz finding: a speed of twenty digits overflowed while it was read; it is too fast (#94).
TEST(Pmc960Cam, ASpeedOfManyDigitsIsTooFastNotAnOverflow) {
    TestDrive t;
    t.enable();
    EXPECT_EQ(t.type("C1000:55555555555555555555\r"), refused("C1000:55555555555555555555", "94"));
    EXPECT_FALSE(t.drive.state().motion.moving());
}

TEST(Pmc960Cam, ReversingWithoutStoppingIs82) {
    TestDrive t;
    t.enable();
    t.type("C1000:100\r", 300ms); // holding 100 forward, past 1000
    EXPECT_EQ(t.type("C500:0\r"), refused("C500:0", "82"));
    EXPECT_EQ(t.type("V!"), prompted("V!100")); // the cam runs on
}

TEST(Pmc960Cam, ARampTooLongIs83) {
    TestDrive t;
    t.enable();
    EXPECT_EQ(t.type("C1000000:1\r"), refused("C1000000:1", "83")); // 100 counts/s over 10^6 counts
}

TEST(Pmc960Cam, CamDuringAnotherMotionIs84) {
    TestDrive t;
    t.enable();
    t.type("I100000+\r", 20ms);
    EXPECT_EQ(t.type("C5000:10\r"), refused("C5000:10", "84"));
}

TEST(Pmc960Cam, ASegmentEndingWhereThePreviousEndsIs85) {
    TestDrive t;
    t.enable();
    t.type("C1000:100\r");
    EXPECT_EQ(t.type("C1000:50\r"), refused("C1000:50", "85"));
}

TEST(Pmc960Cam, ARampSteeperThanAIs86) {
    TestDrive t;
    t.enable();
    t.type("A1\r"); // 1,000 counts/s²
    EXPECT_EQ(t.type("C10:100\r"), refused("C10:100", "86"));
    EXPECT_EQ(t.type("A4000\r"), prompted("A4000"));
    EXPECT_EQ(t.type("C100:100\r"), prompted("C100:100")); // 500,000 of 4,000,000 counts/s²
}

TEST(Pmc960Cam, EscDuringTheCaretWaitIs89) {
    TestDrive t;
    t.enable();
    t.type("C1000:100\r");
    EXPECT_EQ(t.type("C^"), "C^");
    EXPECT_EQ(t.type("\x1b"), "#89" + std::string(kPrompt));
}

TEST(Pmc960Cam, AThirdSegmentWhileOneWaitsIs8A) {
    TestDrive t;
    t.enable();
    t.type("C1000:100\r");
    EXPECT_EQ(t.type("C2000\r"), prompted("C2000"));
    EXPECT_EQ(t.type("C3000\r"), refused("C3000", "8A"));
}

} // namespace
} // namespace pmc960_test
