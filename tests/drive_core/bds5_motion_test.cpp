// BDS5 motion commands on the profile generator: checks before motion, buffering and idling, W, SEG.
// (The motor follows through the simulated loops: PFB trails PCMD by the following error and settles.)
#include "bds5_test_drive.h"

using namespace bds5_test;

namespace {
std::string value(TestDrive& t, const std::string& name) {
    const std::string out = t.type("P " + name + "\r");
    const auto start = out.find("\r\n") + 2;
    const auto end = out.find("\r\n", start);
    std::string v = out.substr(start, end - start);
    v.erase(0, v.find_first_not_of(' '));
    return v;
}
} // namespace

TEST(Bds5Motion, NeedsAnEnabledDrive) { // L6039-6050
    TestDrive t;
    t.type("DIS\r");
    const std::string out = t.type("J 100\r");
    EXPECT_NE(out.find("\aERR 50 'J 100'"), std::string::npos) << out;
    EXPECT_TRUE(out.ends_with("DRIVE INHIBITED\r\n-->"));
}

TEST(Bds5Motion, IncrementalMoveLandsOnItsEnd) { // examples/bds5/05, L2385-2401
    TestDrive t;
    t.type("PLIM OFF\r"); // soft limits PMAX/PMIN are +-100 counts at first (L1548)
    t.type("EN\r");
    t.type("ACC=1000\r");
    t.type("DEC=1000\r");
    EXPECT_EQ(t.type("MI 4000 100\r"), "MI 4000 100\r\n-->");
    EXPECT_EQ(value(t, "SEG"), "1");
    t.wait(100ms);
    EXPECT_EQ(value(t, "VCMD"), "100") << "100 RPM reached after 0.1 s at 1000 RPM/s";
    EXPECT_EQ(value(t, "SEG"), "2");
    EXPECT_EQ(value(t, "PFNL"), "4000");
    t.wait(1000ms);
    EXPECT_EQ(value(t, "PFB"), "4000");
    EXPECT_EQ(value(t, "SEG"), "0");
    t.type("MI -8000\r");
    t.wait(100ms);
    EXPECT_EQ(value(t, "VCMD"), "-1") << "VDEFAULT: 1 RPM";
}

TEST(Bds5Motion, TypedThirdMoveIsErr30) { // L7242
    TestDrive t;
    t.type("PLIM OFF\r"); // soft limits PMAX/PMIN are +-100 counts at first (L1548)
    t.type("EN\r");
    t.type("MI 100000 10\r");
    t.type("MI 100000 10\r");
    EXPECT_NE(t.type("MI 100000 10\r").find("\aERR 30"), std::string::npos);
}

TEST(Bds5Motion, VelocityOutOfBoundsIsErr33) {
    TestDrive t;
    t.type("PLIM OFF\r"); // soft limits PMAX/PMIN are +-100 counts at first (L1548)
    t.type("EN\r");
    EXPECT_NE(t.type("J 8000\r").find("\aERR 33"), std::string::npos) << "VMAX is 7500 RPM";
    EXPECT_NE(t.type("MA 100 -5\r").find("\aERR 33"), std::string::npos);
}

TEST(Bds5Motion, StopDeceleratesAtAmaxAndJogZeroAtDec) {
    TestDrive t;
    t.type("PLIM OFF\r"); // soft limits PMAX/PMIN are +-100 counts at first (L1548)
    t.type("EN\r");
    t.type("ACC=10000\r");
    t.type("DEC=1000\r");
    t.type("J 1000\r");
    t.wait(200ms);
    t.type("J 0\r");
    t.wait(500ms);
    EXPECT_NE(value(t, "VCMD"), "0") << "J 0 decelerates at DEC: a second from 1000 RPM";
    t.type("S\r");
    t.wait(50ms);
    EXPECT_EQ(value(t, "VCMD"), "0") << "S uses AMAX";
}

// PS names what the drive is doing (Table 4.4 L4347-4356): JOG while jogging, PROFILE while a profile
// executes, GEAR in gear mode; ACTIVE is "active, but no motion".
TEST(Bds5Motion, PrintStatusSaysJogProfileAndGear) {
    TestDrive t;
    t.type("PLIM OFF\r"); // soft limits PMAX/PMIN are +-100 counts at first (L1548)
    t.type("EN\r");
    EXPECT_EQ(t.type("PS\r"), "PS\r\nACTIVE\r\n-->");
    t.type("J 100\r", 50ms);
    EXPECT_EQ(t.type("PS\r"), "PS\r\nJOG\r\n-->");
    EXPECT_EQ(t.type("PS \"AXIS \"\r"), "PS \"AXIS \"\r\nAXIS  JOG\r\n-->") << "appended to the line";
    t.type("S\r", 100ms);
    EXPECT_EQ(t.type("PS\r"), "PS\r\nACTIVE\r\n-->") << "stopped";
    t.type("MI 4000 100\r"); // 4000 counts at 100 RPM (6827 counts/s): about 0.6 s
    EXPECT_EQ(t.type("PS\r"), "PS\r\nPROFILE\r\n-->");
    t.wait(2000ms);
    EXPECT_EQ(t.type("PS\r"), "PS\r\nACTIVE\r\n-->") << "the move has ended";
    t.type("GEAR ON\r");
    EXPECT_EQ(t.type("PS\r"), "PS\r\nGEAR\r\n-->");
}

TEST(Bds5Motion, ProgramIdlesOnAFullBufferWhileBackgroundRuns) { // examples/bds5/41, L4645-4687
    TestDrive t;
    t.download({"1$", "PLIM OFF", "EN", "MI 1000 10", "P \"FIRST MOVE PROCESSED\"", "MI 1000 10",
                "P \"SECOND MOVE PROCESSED\"", "MI 1000 10", "P \"THIRD MOVE PROCESSED\"", "B", "BACKGROUND$",
                "P \"UPPER TASK IDLED\"", "D 250", "END"});
    t.type("ACC=1000\r");
    t.type("DEC=1000\r");
    const std::string out = t.type("RUN 1\r", 4000ms);
    const auto second = out.find("SECOND MOVE PROCESSED");
    const auto third = out.find("THIRD MOVE PROCESSED");
    ASSERT_NE(second, std::string::npos) << out;
    ASSERT_NE(third, std::string::npos) << out;
    EXPECT_GE(count(out.substr(second, third - second), "UPPER TASK IDLED"), 5) << out;
}

TEST(Bds5Motion, WaitZeroHoldsUntilMotionStops) { // examples/bds5/42, L4700-4750
    TestDrive t;
    t.download({"1$", "PLIM OFF", "EN", "MI 2000 100", "P \"MOVE PROCESSED\"", "W 0", "P \"ALL MOTION STOPPED\"",
                "P PCMD", "B"});
    t.type("ACC=1000\r");
    t.type("DEC=1000\r");
    const std::string early = t.type("RUN 1\r", 150ms); // the move takes about 0.4 s
    EXPECT_NE(early.find("MOVE PROCESSED"), std::string::npos);
    EXPECT_EQ(early.find("ALL MOTION STOPPED"), std::string::npos);
    const std::string late = t.wait(2000ms);
    EXPECT_EQ(late, "ALL MOTION STOPPED\r\n        2000\r\n-->") << "the command has landed";
    EXPECT_EQ(value(t, "PFB"), "2000") << "and the motor has settled on it";
}

TEST(Bds5Motion, WaitForSegmentTwo) {
    TestDrive t;
    t.download({"1$", "PLIM OFF", "EN", "MI 5000 100", "W 2", "P SEG[1] VCMD[4]", "B"});
    t.type("ACC=1000\r");
    EXPECT_NE(t.type("RUN 1\r", 300ms).find("2 100\r\n-->"), std::string::npos);
}

TEST(Bds5Motion, NormalizeOnlyAtRest) {
    TestDrive t;
    t.type("PLIM OFF\r"); // soft limits PMAX/PMIN are +-100 counts at first (L1548)
    t.type("EN\r");
    t.type("NORM 500\r");
    EXPECT_EQ(value(t, "PFB"), "500");
    t.type("J 10\r");
    EXPECT_NE(t.type("NORM 0\r").find("\aERR 57"), std::string::npos);
}

TEST(Bds5Macro, Example1ElevenThousandCountsInFiveSegments) { // L2534-2552
    TestDrive t;
    t.type("PLIM OFF\r"); // soft limits PMAX/PMIN are +-100 counts at first (L1548)
    t.type("EN\r");
    t.type("ACC=20000\r");
    t.type("DEC=20000\r");
    EXPECT_EQ(t.type("MCI 10000 1000 200\r"), "MCI 10000 1000 200\r\n-->");
    EXPECT_EQ(t.type("MCI 1000 0\r"), "MCI 1000 0\r\n-->");
    t.type("RECORD 1000 1 SEG\r");
    EXPECT_EQ(t.type("MCGO\r"), "MCGO\r\n-->");
    EXPECT_EQ(value(t, "PFNL"), "11000");
    t.wait(1500ms);
    EXPECT_EQ(value(t, "PFB"), "11000");
    const std::string play = t.type("PLAY\r");
    EXPECT_NE(play.find("           5\r\n"), std::string::npos) << "the fifth segment ran";
    EXPECT_EQ(play.find("           6\r\n"), std::string::npos);
    t.type("MCGO\r");
    t.wait(1500ms);
    EXPECT_EQ(value(t, "PFB"), "22000") << "every MCGO repeats the move";
}

TEST(Bds5Macro, Example2DwellsAndReturnsHome) { // L2569-2576
    TestDrive t;
    t.type("PLIM OFF\r"); // soft limits PMAX/PMIN are +-100 counts at first (L1548)
    t.type("EN\r");
    t.type("ACC=20000\r");
    t.type("DEC=20000\r");
    for (const char* line : {"MCA 10000 1000 200", "MCA 11000 0", "MCD 500", "MCA 0 1000 0", "MCGO"})
        EXPECT_EQ(t.type(std::string(line) + "\r"), std::string(line) + "\r\n-->");
    t.wait(500ms);
    EXPECT_EQ(value(t, "PFB"), "11000") << "out in about 0.35 s, then the 0.5 s dwell";
    EXPECT_EQ(value(t, "SEG"), "6") << "segment 6 is the dwell";
    t.wait(3000ms);
    EXPECT_EQ(value(t, "PFB"), "0");
}

TEST(Bds5Macro, ErrorsOfTheManual) { // L7260-7279
    TestDrive t;
    t.type("PLIM OFF\r"); // soft limits PMAX/PMIN are +-100 counts at first (L1548)
    t.type("EN\r");
    t.type("MCI 1000 100 50\r");
    EXPECT_NE(t.type("MCGO\r").find("\aERR 43"), std::string::npos) << "last section not at rest";
    EXPECT_NE(t.type("MCD 100\r").find("\aERR 44"), std::string::npos);
    EXPECT_NE(t.type("MCI -100\r").find("\aERR 40"), std::string::npos) << "reversing at speed";
    EXPECT_NE(t.type("MCI 1 1000 0\r").find("\aERR 42"), std::string::npos) << "too short for the speeds";
    t.type("DIS\r");
    t.type("PLIM OFF\r"); // soft limits PMAX/PMIN are +-100 counts at first (L1548)
    t.type("EN\r");       // enabling resets the macro memory
    EXPECT_NE(t.type("MCI 100\r").find("\aERR 41"), std::string::npos) << "no speed from rest";
}

TEST(Bds5JogTo, ChangesSpeedSoTheRampEndsAtThePosition) { // L2734-2800
    TestDrive t;
    t.type("PLIM OFF\r"); // soft limits PMAX/PMIN are +-100 counts at first (L1548)
    t.type("EN\r");
    t.type("ACC=10000\r");
    t.type("DEC=10000\r");
    EXPECT_NE(t.type("JT 1000 0\r").find("\aERR 41"), std::string::npos) << "JT needs motion";
    t.type("J 100\r");
    t.wait(50ms);
    EXPECT_EQ(t.type("JT 20000 0\r"), "JT 20000 0\r\n-->");
    t.wait(4000ms);
    EXPECT_EQ(value(t, "PFB"), "20000");
    EXPECT_EQ(value(t, "VCMD"), "0");
    t.type("J 100\r");
    t.wait(50ms);
    EXPECT_NE(t.type("JT 0 0\r").find("\aERR 42"), std::string::npos) << "already passed";
    EXPECT_NE(t.type("JF 99999 -10\r").find("\aERR 40"), std::string::npos);
}

TEST(Bds5Mrd, MovesTheShortWayWithinARevolution) { // L2581-2613
    TestDrive t;
    t.type("PLIM OFF\r"); // soft limits PMAX/PMIN are +-100 counts at first (L1548)
    t.type("EN\r");
    t.type("NORM 4000\r");
    t.type("MRD 100 100\r");
    t.wait(500ms);
    EXPECT_EQ(value(t, "PFB"), "4196") << "4000 is R/D 4000: forward 196 to 100";
    t.type("MRD 4000 100 CW\r");
    t.wait(2000ms);
    EXPECT_EQ(value(t, "PFB"), "8096");
}

TEST(Bds5Gate, MotionWaitsForTheGateInput) { // L5949-5971
    TestDrive t;
    t.type("PLIM OFF\r");
    t.type("EN\r");
    t.type("GATEMODE ON\r");
    t.type("MI 1000 100\r");
    t.type("MI -1000\r");
    t.wait(200ms);
    EXPECT_EQ(value(t, "PFB"), "0") << "precalculated, waiting for GATE";
    t.drive.setDedicatedInput("GATE", true);
    t.wait(300ms);
    EXPECT_EQ(value(t, "GATEMODE"), "0") << "GATEMODE turns off once motion begins";
    EXPECT_NE(value(t, "PFB"), "0");
    EXPECT_NE(t.type("GATEMODE ON\r").find("\aERR 57"), std::string::npos) << "not while motion is commanded";
}

TEST(Bds5Gate, TurningGatemodeOffForgetsTheMotion) {
    TestDrive t;
    t.type("PLIM OFF\r");
    t.type("EN\r");
    t.type("GATEMODE ON\r");
    t.type("MI 1000 100\r");
    t.type("GATEMODE OFF\r");
    t.wait(500ms);
    EXPECT_EQ(value(t, "PFB"), "0");
    EXPECT_EQ(value(t, "SEG"), "0");
}
