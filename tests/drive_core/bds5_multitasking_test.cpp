// Multitasking (Table 4.5): background, alarms, VARIABLE$, HOLD, timers — the manual's examples.
#include "bds5_test_drive.h"

using namespace bds5_test;
using drive_core::bds5::Bds5DriveMode;

TEST(Bds5Multitasking, BackgroundRunsEvery500msAfterBareRun) { // examples/bds5/49, L5006-5015
    TestDrive t;
    t.download({"BACKGROUND$", "P \"EXECUTING BACKGROUND\"", "D 500", "END"});
    EXPECT_EQ(t.type("RUN\r", 10ms), "RUN\r\nEXECUTING BACKGROUND\r\n");
    // Each pass costs the print, the 500 ms dwell and END: about 508 ms, so four more in 2.1 s.
    const std::string out = t.wait(2100ms);
    EXPECT_EQ(count(out, "EXECUTING BACKGROUND\r\n"), 4) << out;
    EXPECT_EQ(t.drive.mode(), Bds5DriveMode::Running);
    EXPECT_EQ(t.type("\x18"), "-->") << "^X breaks multitasking";
}

TEST(Bds5Multitasking, BackgroundRunsWhileMainDwells) {
    TestDrive t;
    t.download({"1$", "P \"MAIN\"", "D 1000", "P \"MAIN DONE\"", "B", "BACKGROUND$", "P \"BG\"", "D 250", "END"});
    const std::string out = t.type("RUN 1\r", 1100ms);
    EXPECT_EQ(out.find("RUN 1\r\nMAIN\r\nBG\r\n"), 0u) << out;
    EXPECT_EQ(count(out, "BG\r\n"), 4) << out;
    EXPECT_TRUE(out.ends_with("MAIN DONE\r\n-->")) << out;
}

TEST(Bds5Multitasking, AlarmFiresOnTheInputEdge) { // examples/bds5/43, L4783-4790
    TestDrive t;
    t.download({"1$", "X1=X1+1", "GOTO 1", "A$ I1 ON", "OUT = 0", "P \"ALARM\"", "B"});
    t.type("O2=ON\r");
    EXPECT_EQ(t.type("RUN 1\r", 100ms), "RUN 1\r\n") << "the main loop runs, the alarm waits";
    t.drive.setInput(1, true);
    EXPECT_EQ(t.wait(20ms), "ALARM\r\n-->");
    EXPECT_EQ(t.type("P OUT\r"), "P OUT\r\n           0\r\n-->");
    EXPECT_EQ(t.drive.mode(), Bds5DriveMode::Interactive);
}

TEST(Bds5Multitasking, AlarmWhoseSwitchIsAlreadyOnFiresAtRun) { // L6582
    TestDrive t;
    t.download({"1$", "D 10000", "A$ XS1 ON", "P \"FIRED\"", "END"});
    t.type("XS1=1\r");
    EXPECT_EQ(t.type("RUN 1\r", 20ms), "RUN 1\r\nFIRED\r\n");
}

TEST(Bds5Multitasking, VariableTaskOnCtrlV) { // examples/bds5/45 (INPUT replaced: INPUT comes later)
    TestDrive t;
    t.download({"VARIABLE$", "P \"X1 IS \" X1[1]", "END", "10$", "X1=0", "11$", "X1=X1+1", "D 100", "GOTO 11"});
    EXPECT_EQ(t.type("RUN 10\r", 250ms), "RUN 10\r\n");
    const std::string out = t.type("\x16", 5ms);
    EXPECT_TRUE(out == "X1 IS 3\r\n") << out;
}

TEST(Bds5Multitasking, HoldWaitsForTheSwitch) { // examples/bds5/38, L4466-4470
    TestDrive t;
    t.download({"29$", "H I1 ON", "P \"I1 IS ON\"", "B"});
    EXPECT_EQ(t.type("RUN 29\r", 500ms), "RUN 29\r\n");
    t.drive.setInput(1, true);
    EXPECT_EQ(t.wait(10ms), "I1 IS ON\r\n-->");
}

TEST(Bds5Multitasking, HoldRefusesRemote) {
    TestDrive t;
    t.download({"1$", "H REMOTE ON"});
    EXPECT_NE(t.type("RUN 1\r", 10ms).find("ERR 89 LINE 2 'REMOTE'"), std::string::npos);
}

TEST(Bds5Multitasking, TimersCountDownInMilliseconds) {
    TestDrive t;
    t.download({"1$", "TMR1=300", "TIL TMR1 EQ 0", "P \"DONE\"", "B"});
    EXPECT_EQ(t.type("RUN 1\r", 290ms), "RUN 1\r\n");
    EXPECT_EQ(t.wait(20ms), "DONE\r\n-->");
}

TEST(Bds5Multitasking, EndWithoutDedicatedTasksIsBreak) { // L4579-4601
    TestDrive t;
    t.download({"1$", "P \"ONCE\"", "END"});
    EXPECT_EQ(t.type("RUN 1\r", 20ms), "RUN 1\r\nONCE\r\n-->");
}

TEST(Bds5Multitasking, GotoIsNotAllowedInBackground) {
    TestDrive t;
    t.download({"BACKGROUND$", "GOTO 1", "1$", "END"});
    EXPECT_NE(t.type("RUN\r", 20ms).find("ERR 63 LINE 2"), std::string::npos);
}

TEST(Bds5Io, OutputsAndTheOutWord) { // L1662-1667
    TestDrive t;
    EXPECT_EQ(t.type("O1=ON\r"), "O1=ON\r\n-->");
    EXPECT_EQ(t.type("P OUT\r"), "P OUT\r\n           1\r\n-->");
    EXPECT_TRUE(t.drive.output(1));
    t.type("OUT=0C8H\r");
    EXPECT_FALSE(t.drive.output(1));
    EXPECT_TRUE(t.drive.output(4) && t.drive.output(7) && t.drive.output(8));
    EXPECT_EQ(t.type("P O4\r"), "P O4\r\n           1\r\n-->");
}

TEST(Bds5Io, InputsAndTheInWord) {
    TestDrive t;
    t.drive.setInput(2, true);
    t.drive.setInput(5, true);
    EXPECT_EQ(t.type("P IN\r"), "P IN\r\n          18\r\n-->");
    EXPECT_EQ(t.type("P I5\r"), "P I5\r\n           1\r\n-->");
}

TEST(Bds5Multitasking, RegulatedDwellWaitsForTheExternalInput) { // L5823-5839
    TestDrive t;
    t.download({"45$", "REGKHZ=100", "RD 2000", "P \"DONE\"", "B"});
    EXPECT_EQ(t.type("RUN 45\r", 3000ms), "RUN 45\r\n") << "the master encoder stands still: RD does not end";
    EXPECT_EQ(t.type("\x18"), "-->");
}
