// RECORD/PLAY, RAND, the v3 real-time trace, MOTOR, and the AUTO$/MANUAL$ tasks.
#include "bds5_test_drive.h"

using namespace bds5_test;

TEST(Bds5Record, RecordsAJogAndPlaysItBack) { // L6370-6397: RECORD 500 1 VFB then J 1000
    TestDrive t;
    t.type("PLIM OFF\r"); // soft limits PMAX/PMIN are +-100 counts at first (L1548)
    t.type("EN\r");
    t.type("ACC=10000\r");
    EXPECT_EQ(t.type("RECORD 200 1 VCMD PCMD\r"), "RECORD 200 1 VCMD PCMD\r\n-->");
    t.type("J 1000\r");
    t.wait(300ms);
    const std::string out = t.type("PLAY\r");
    ASSERT_EQ(out.find("PLAY\r\nRECORD 200 1 VCMD PCMD\r\n"), 0u) << out.substr(0, 100);
    EXPECT_EQ(count(out, "\r\n"), 1 + 1 + 200) << "the set-up line and 200 samples";
    EXPECT_NE(out.find("        1000"), std::string::npos) << "the jog reached 1000 RPM while recording";
    EXPECT_TRUE(out.ends_with("\r\n-->"));
}

// The layout the PLAY help (catalog) describes: the set-up line, then one line per instant with the values
// in RECORD order, integers in user units right-justified in 12 columns.
TEST(Bds5Record, PlayListsOneLinePerInstantInRecordOrder) {
    TestDrive t;
    t.type("X1=5\r");
    t.type("X2=-7\r");
    t.type("PNUM=4096\r"); // degrees
    t.type("PDEN=360\r");
    t.type("PFB=90\r");
    t.type("RECORD 2 1 X2 X1 PFB\r");
    t.wait(10ms);
    const std::string row = "          -7           5          90\r\n";
    EXPECT_EQ(t.type("PLAY\r"), "PLAY\r\nRECORD 2 1 X2 X1 PFB\r\n" + row + row + "-->");
}

TEST(Bds5Record, LimitsAndErrors) {
    TestDrive t;
    EXPECT_NE(t.type("PLAY\r").find("\aERR 65"), std::string::npos) << "nothing recorded since power-up";
    EXPECT_NE(t.type("RECORD 600 1 VFB PCMD\r").find("\aERR 90"), std::string::npos) << "1200 points";
    EXPECT_NE(t.type("RECORD 100 1 PE\r").find("\aERR 89 'PE'"), std::string::npos);
    EXPECT_NE(t.type("RECORD 100 1 XS1\r").find("\aERR 89"), std::string::npos);
    EXPECT_EQ(t.type("RECORD 250 1 X1 X2 X3 X4\r"), "RECORD 250 1 X1 X2 X3 X4\r\n-->");
}

TEST(Bds5Record, SamplesFollowTheInterval) {
    TestDrive t;
    t.download({"1$", "X1=0", "2$", "X1=X1+1", "D 8", "GOTO 2"});
    t.type("RECORD 5 100 X1\r");
    t.type("RUN 1\r", 600ms);
    t.type("\x18");
    const std::string out = t.type("PLAY\r");
    // Samples every 100 ms of a counter stepping every 14.6 ms (label 1 + assignment 2 + D line 2 + 8 ms
    // dwell + GOTO 1.6): 6.85 a sample. The first interval also holds the RUN's start.
    std::vector<int> values;
    for (std::size_t at = out.find("X1\r\n") + 4; at + 12 <= out.size() && values.size() < 5; at += 14)
        values.push_back(std::stoi(out.substr(at, 12)));
    ASSERT_EQ(values.size(), 5u) << out;
    for (std::size_t i = 2; i < values.size(); ++i) EXPECT_NEAR(values[i] - values[i - 1], 6.85, 0.9) << out;
}

TEST(Bds5Random, SeededNumbersStayWithinBounds) { // v3 L9310
    TestDrive t;
    t.type("RAND 42\r");
    for (int i = 0; i < 20; ++i) {
        t.type("RAND X1 -10 10\r");
        const std::string out = t.type("P X1\r");
        const int v = std::stoi(out.substr(out.find("\r\n") + 2, 12));
        EXPECT_GE(v, -10);
        EXPECT_LE(v, 10);
    }
    EXPECT_NE(t.type("RAND X1 0 40000\r").find("\aERR 83"), std::string::npos);
}

TEST(Bds5RealTimeTrace, RecordsExecutedLines) { // v3 L9317-9319
    TestDrive t;
    t.download({"5$", "X1=1", "B"});
    t.type("TRECORD START\r");
    t.type("RUN 5\r", 20ms);
    EXPECT_EQ(t.type("TPLAY\r"), "TPLAY\r\n#1 LINE 1 t... 5$\r\n#2 LINE 2 t... X1=1\r\n#3 LINE 3 t... B\r\n-->");
    EXPECT_EQ(t.type("TPLAY NEWEST 1\r"), "TPLAY NEWEST 1\r\n#3 LINE 3 t... B\r\n-->");
}

// "Display the present motor drive combination" (L6925): the motor on the bench, which the bench can swap
// (issue 20, item 13: it printed one fixed motor whatever was fitted).
TEST(Bds5Motor, ShowsThePresentMotor) {
    TestDrive t;
    EXPECT_EQ(t.type("MOTOR\r"), "MOTOR\r\nMOTOR: REF-MEDIUM (1.2 kW, 3 Nm continuous, 6000 RPM (the default)), 12-BIT "
                                 "R/D, VMAX 7500 RPM\r\n-->");
    ASSERT_TRUE(t.drive.controls()->selectMotor("REF-LARGE"));
    t.wait(2000ms);
    const std::string shown = t.type("MOTOR\r");
    EXPECT_NE(shown.find("MOTOR: REF-LARGE (3.5 kW, 14 Nm continuous"), std::string::npos) << shown;
}

TEST(Bds5AutoManual, CycleStartsAutoAndManualRunsWhileOn) { // L4960-4997
    TestDrive t;
    t.download({"AUTO$", "X1=X1+1", "END", "MANUAL$", "X2=X2+1", "D 100", "END"});
    t.type("RUN\r", 50ms);
    t.drive.setDedicatedInput("CYCLE", true);
    t.wait(50ms);
    t.drive.setDedicatedInput("CYCLE", false);
    t.drive.setDedicatedInput("MANUAL", true);
    t.wait(450ms);
    t.drive.setDedicatedInput("MANUAL", false);
    t.type("\x18");
    EXPECT_EQ(t.type("P X1\r"), "P X1\r\n           1\r\n-->");
    const std::string x2 = t.type("P X2\r");
    EXPECT_EQ(x2, "P X2\r\n           5\r\n-->") << "MANUAL$ restarted every ~105 ms for 450 ms";
}
