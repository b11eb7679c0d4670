// INPUT, single-step, trace, ERROR$ and the print variants — the manual's examples (§4.10, §5.2, §4.9).
#include "bds5_test_drive.h"

#include <algorithm>

using namespace bds5_test;
using drive_core::bds5::Bds5DriveMode;

namespace {
const std::vector<std::string> kNestedIf = {"55$",
                                            "IF X1 GT 0",
                                            "  IF X2 GT 0",
                                            "    P \"BOTH X1 AND X2 > 0\"",
                                            "  ELSE",
                                            "    P \"ONLY X1 GT 0\"",
                                            "  ENDIF",
                                            "ELSE",
                                            "  IF X2 GT 0",
                                            "    P \"ONLY X2 GT 0\"",
                                            "  ELSE",
                                            "    P \"NEITHER X1 NOR X2 > 0\"",
                                            "  ENDIF",
                                            "ENDIF",
                                            "B"};
} // namespace

TEST(Bds5Input, DecimalScaling44) { // examples/bds5/35, L4428-4435
    TestDrive t;
    t.download({"44$", "INPUT \"ENTER NEW POSITION: \" X1[3]", "P \"NEW POSITION = \" X1[.3]",
                "P \"ACTUALLY, X1= \" X1", "B"});
    EXPECT_EQ(t.type("RUN 44\r", 20ms), "RUN 44\r\nENTER NEW POSITION: ");
    EXPECT_EQ(t.drive.mode(), Bds5DriveMode::Running);
    EXPECT_EQ(t.type("1.234\r", 50ms), "1.234\r\nNEW POSITION =        1.234\r\nACTUALLY, X1=         1234\r\n-->");
}

TEST(Bds5Input, LimitsAreEnforcedAndTheQuestionRepeats) {
    TestDrive t;
    t.download({"1$", "INPUT \"X2? \" X2 10 100", "P X2[3]", "B"});
    t.type("RUN 1\r", 20ms);
    const std::string out = t.type("5\r", 20ms);
    EXPECT_NE(out.find("\aERR 83 '5'"), std::string::npos) << out;
    EXPECT_TRUE(out.ends_with("X2? ")) << out;
    EXPECT_EQ(t.type("50\r", 20ms), "50\r\n 50\r\n-->");
}

TEST(Bds5Input, EmptyAnswerKeepsTheValueAndOnIsOne) {
    TestDrive t;
    t.type("X3=7\r");
    t.download({"1$", "INPUT \"A \" X3", "INPUT \"B \" XS1", "P X3[1] XS1[1]", "B"});
    t.type("RUN 1\r", 20ms);
    t.type("\r", 20ms);
    EXPECT_EQ(t.type("ON\r", 20ms), "ON\r\n71\r\n-->");
}

TEST(Bds5Input, DotFormatIsBadInInput) { // L7358-7366
    TestDrive t;
    t.download({"1$", "INPUT \"X \" X1[.3]", "B"});
    EXPECT_NE(t.type("RUN 1\r", 20ms).find("ERR 79 LINE 2"), std::string::npos);
}

TEST(Bds5SingleStep, StepsThroughTheNestedIf) { // L5641-5682
    TestDrive t;
    t.download(kNestedIf);
    t.type("X1=1\r");
    t.type("X2=1\r");
    t.type("SS ON\r");
    EXPECT_EQ(t.type("RUN 55\r", 20ms), "RUN 55\r\n55$\r\ns-->");
    EXPECT_EQ(t.drive.mode(), Bds5DriveMode::SingleStep);
    EXPECT_EQ(t.type("\r", 20ms), "\r\nIF X1 GT 0\r\ns-->");
    EXPECT_EQ(t.type("P X1\r", 20ms), "P X1\r\n           1\r\ns-->") << "probe without stepping";
    EXPECT_EQ(t.type("\r", 20ms), "\r\n  IF X2 GT 0\r\ns-->");
    EXPECT_EQ(t.type("\r", 20ms), "\r\n    P \"BOTH X1 AND X2 > 0\"\r\ns-->");
    EXPECT_EQ(t.type("\r", 20ms), "\r\nBOTH X1 AND X2 > 0\r\n  ELSE\r\ns-->");
    EXPECT_EQ(t.type("SS OFF\r", 50ms), "SS OFF\r\n-->") << "SS OFF at the prompt runs on to the B";
}

TEST(Bds5Trace, ShowsOnlyTheExecutedLines) { // L5686-5712
    TestDrive t;
    t.download(kNestedIf);
    t.type("X1=1\r");
    t.type("X2=1\r");
    t.type("TRC ON\r");
    EXPECT_EQ(t.type("RUN 55\r", 200ms), "RUN 55\r\n"
                                         "t...55$\r\n"
                                         "t...IF X1 GT 0\r\n"
                                         "t...  IF X2 GT 0\r\n"
                                         "t...    P \"BOTH X1 AND X2 > 0\"\r\n"
                                         "BOTH X1 AND X2 > 0\r\n"
                                         "t...  ELSE\r\n"
                                         "t...  ENDIF\r\n"
                                         "t...ELSE\r\n"
                                         "t...ENDIF\r\n"
                                         "t...B\r\n"
                                         "-->");
}

TEST(Bds5Trace, BackgroundLinesCarryTheirTask) { // L5728-5758
    TestDrive t;
    t.download({"BACKGROUND$", "P \"UPPER TASK IDLED\"", "D 250", "END"});
    t.type("TRC ON\r");
    const std::string out = t.type("RUN\r", 100ms);
    EXPECT_NE(out.find("t.*.P \"UPPER TASK IDLED\"\r\nUPPER TASK IDLED\r\n"), std::string::npos) << out;
}

// Trace lines are output like prints: each waits for the line (L4637), so a background loop that
// traces faster than 9600 baud carries cannot bury the main task's print nor outlive ^X.
namespace {
const std::vector<std::string> kTracedLoop = {"1$", "D 100", "P \"MAIN DONE\"", "B", "BACKGROUND$", "X1=X1+1", "END"};
// 9600 baud carries 960 characters a second; a traced line and its print (at most 4 + 80 + 2 and 80 + 2
// characters) are under 0.2 s of it. Without pacing the loop writes 24 characters each 4.25 ms.
constexpr std::size_t kLineBacklog = 192;

// Steps in 1 ms ticks until `needle` has been sent or `limit` has passed; returns what was sent.
std::string runUntil(TestDrive& t, const std::string& needle, std::chrono::milliseconds limit) {
    std::string out;
    for (auto ms = 0ms; ms < limit && out.find(needle) == std::string::npos; ms += 1ms) {
        t.drive.step(1ms);
        out += t.drive.takeTransmitted();
    }
    return out;
}
} // namespace

TEST(Bds5Trace, MainTaskPrintsBesideATracedBackgroundLoop) { // L4623-4640, L5728-5758
    TestDrive t;
    t.download(kTracedLoop);
    t.type("TRC ON\r");
    t.drive.receive("RUN 1\r");
    // D 100, then the print waits at most for the trace line on the wire (about 15 ms).
    const std::string out = runUntil(t, "\r\nMAIN DONE\r\n", 300ms);
    const auto done = out.find("t...P \"MAIN DONE\"\r\nMAIN DONE\r\n");
    ASSERT_NE(done, std::string::npos) << out;
    EXPECT_NE(out.find("t...D 100\r\nt.*.X1=X1+1\r\n"), std::string::npos) << "the background runs while main dwells";
    EXPECT_TRUE(t.wait(100ms).starts_with("t...B\r\n")) << "the main task goes on to its break";
    EXPECT_EQ(t.drive.mode(), Bds5DriveMode::Interactive);
}

TEST(Bds5Trace, TransmitBacklogStaysWithinALinesWorth) { // L4637
    TestDrive t;
    t.download({"1$", "D 50", "P \"MAIN\"", "GOTO 1", "BACKGROUND$", "X1=X1+1", "END"});
    t.type("TRC ON\r");
    t.drive.receive("RUN 1\r");
    std::string out;
    std::size_t worst = 0;
    for (auto ms = 0ms; ms < 1000ms; ms += 1ms) {
        t.drive.step(1ms);
        worst = std::max(worst, t.drive.transmitBacklog());
        out += t.drive.takeTransmitted();
    }
    EXPECT_LE(worst, kLineBacklog);
    EXPECT_GE(out.size(), 800u) << "the trace keeps the 9600-baud line busy";
    EXPECT_GE(count(out, "t...P \"MAIN\"\r\nMAIN\r\n"), 5) << out;
    EXPECT_GE(count(out, "t.*.X1=X1+1\r\n"), 5) << out;
}

TEST(Bds5Trace, CtrlXStopsTheTraceAtOnce) { // L2233-2235, L9868
    TestDrive t;
    t.download({"BACKGROUND$", "X1=X1+1", "END"});
    t.type("TRC ON\r");
    t.drive.receive("RUN\r");
    for (auto ms = 0ms; ms < 1000ms; ms += 1ms) t.drive.step(1ms);
    ASSERT_NE(t.drive.takeTransmitted().find("t.*.X1=X1+1\r\n"), std::string::npos) << "the loop traces";
    const std::size_t queued = t.drive.transmitBacklog(); // what the transmitter holds at the ^X
    t.drive.receive("\x18");
    for (auto ms = 0ms; ms < 3000ms; ms += 1ms) t.drive.step(1ms);
    const std::string out = t.drive.takeTransmitted();
    EXPECT_LE(out.size(), std::min(queued, kLineBacklog) + 5) << out; // + CR LF "-->" at most
    EXPECT_EQ(out.find("t.", std::min(queued, out.size())), std::string::npos) << "no trace after ^X: " << out;
    EXPECT_TRUE(out.ends_with("-->")) << out;
    EXPECT_EQ(t.drive.mode(), Bds5DriveMode::Interactive);
}

TEST(Bds5ErrorLabel, ABreakingErrorRunsErrorLabel) { // L4956-4958
    TestDrive t;
    t.download({"1$", "X1=1/0", "P \"NOT HERE\"", "B", "ERROR$", "P \"RECOVERING\"", "B"});
    const std::string out = t.type("RUN 1\r", 200ms); // the print waits for the error line to leave
    EXPECT_NE(out.find("ERR 92 LINE 2"), std::string::npos) << out;
    EXPECT_TRUE(out.ends_with("ZERO DIVIDE\r\nRECOVERING\r\n-->")) << out;
    EXPECT_EQ(out.find("NOT HERE"), std::string::npos);
}

TEST(Bds5ErrorLabel, GotoInsideErrorLabelIsErr55) {
    TestDrive t;
    t.download({"1$", "X1=1/0", "2$", "B", "ERROR$", "GOTO 2"});
    const std::string out = t.type("RUN 1\r", 50ms);
    EXPECT_NE(out.find("ERR 55 LINE 6"), std::string::npos) << out;
}

TEST(Bds5Print, RefreshEndsWithCrOnly) { // L4360-4378
    TestDrive t;
    EXPECT_EQ(t.type("R \"ABC\"\r"), "R \"ABC\"\r\nABC\r\r\n-->") << "the prompt needs a CR LF before it";
}

TEST(Bds5Print, StatusWords) { // Table 4.4
    TestDrive t;
    EXPECT_EQ(t.type("PS \"X\"\r"), "PS \"X\"\r\nX OFF\r\n-->");
    t.type("EN\r");
    EXPECT_EQ(t.type("PS\r"), "PS\r\nACTIVE\r\n-->");
}

TEST(Bds5Print, ClearXZeroesUserVariables) { // v3 L9308
    TestDrive t;
    t.type("X9=5\r");
    t.type("XS2=1\r");
    t.type("CLEARX\r");
    EXPECT_EQ(t.type("P X9 XS2\r"), "P X9 XS2\r\n           0           0\r\n-->");
}

TEST(Bds5Units, VelocityReadsInRpmAndStoresBasicUnits) { // Table 4.11: VNUM/VDEN = 44739/10 per RPM
    TestDrive t;
    EXPECT_EQ(t.type("P VMAX\r"), "P VMAX\r\n        7500\r\n-->");
    t.type("VNUM=447392\r");
    t.type("VDEN=100\r");
    EXPECT_EQ(t.type("P VMAX\r"), "P VMAX\r\n        7500\r\n-->") << "the same speed in a finer unit";
}

TEST(Bds5Units, ChangingUnitsReinterpretsStoredValues) { // L5091-5097
    TestDrive t;
    t.type("PNUM=4096\r");
    t.type("PDEN=1\r"); // position in revolutions
    EXPECT_EQ(t.type("PMAX=3\r"), "PMAX=3\r\n-->");
    t.type("PNUM=1\r"); // back to counts: the stored 3 revolutions read as counts
    EXPECT_EQ(t.type("P PMAX\r"), "P PMAX\r\n       12288\r\n-->");
}

TEST(Bds5Units, ScalingOverflowIsErr96) {
    TestDrive t;
    t.type("PNUM=1000000\r");
    const std::string out = t.type("PMAX=1000000\r");
    EXPECT_NE(out.find("\aERR 96"), std::string::npos) << out;
}
