// Program transcripts: download with >BDS as Motion Link does, upload with <BDS, RUN, monitor mode,
// control flow and the errors RUN reports — the bytes the manual's examples show (seed-bds5 §2.9, §4.8, §9).
#include "bds5_test_drive.h"

#include <gtest/gtest.h>

#include <vector>

using drive_core::bds5::Bds5Drive;
using drive_core::bds5::Bds5DriveMode;
using namespace std::chrono_literals;

namespace {

class Bds5Program : public ::testing::Test, public bds5_test::TestDrive {};

} // namespace

TEST_F(Bds5Program, HelloWorldDownloadAndRun) {
    download({"10$", "P \"HELLO WORLD\"", "B"});
    EXPECT_EQ(type("RUN 10\r", 20ms), "RUN 10\r\nHELLO WORLD\r\n-->"); // L3436-3462
    EXPECT_EQ(drive.mode(), Bds5DriveMode::Interactive);
}

TEST_F(Bds5Program, UploadListsEveryLineThenPrompt) {
    download({"10$ ;FIRST", "  P \"HI\"", "B"});
    EXPECT_EQ(type("<BDS\r"), "<BDS\r\n10$ ;FIRST\r\n  P \"HI\"\r\nB\r\n-->");
}

TEST_F(Bds5Program, EscapeBeforeAnyLineKeepsTheProgram) {
    download({"1$", "B"});
    EXPECT_EQ(type(">BDS\r"), ">BDS\r\nl->");
    EXPECT_EQ(type("\x1b"), "\r\n-->");
    EXPECT_EQ(type("<BDS\r"), "<BDS\r\n1$\r\nB\r\n-->");
}

TEST_F(Bds5Program, ChecksumChangesWithTheProgram) {
    download({"1$", "P \"A\"", "B"});
    const std::string first = type("P CHECKSUM\r");
    download({"1$", "P \"B\"", "B"});
    const std::string second = type("P CHECKSUM\r");
    EXPECT_NE(first, second);
    EXPECT_EQ(first.size(), std::string("P CHECKSUM\r\n").size() + 12 + 2 + 3) << first;
}

TEST_F(Bds5Program, GotoDemo) { // examples/bds5/21, L3770-3787
    download({"2$", "P \"AT LABEL 2\"", "GOTO 3$", "P \"NEVER GOT HERE\"", "3$", "P \"AT LABEL 3\"", "B"});
    EXPECT_EQ(type("RUN 2\r", 50ms), "RUN 2\r\nAT LABEL 2\r\nAT LABEL 3\r\n-->");
}

TEST_F(Bds5Program, GosubDemo) { // examples/bds5/22, L3803-3821
    download(
        {"4$", "GOSUB 5$", "P \"RETURNED FROM SUBROUTINE 5\"", "B", ";", "5$", "P \"EXECUTING SUBROUTINE 5\"", "RET"});
    EXPECT_EQ(type("RUN 4\r", 50ms), "RUN 4\r\nEXECUTING SUBROUTINE 5\r\nRETURNED FROM SUBROUTINE 5\r\n-->");
}

TEST_F(Bds5Program, NestedBlockIf) { // examples/bds5/29, L4074-4088
    download({"55$", "IF X1 GT 0", "  IF X2 GT 0", "    P \"BOTH X1 AND X2 > 0\"", "  ELSE", "    P \"ONLY X1 GT 0\"",
              "  ENDIF", "ELSE", "  IF X2 GT 0", "    P \"ONLY X2 GT 0\"", "  ELSE", "    P \"NEITHER X1 NOR X2 > 0\"",
              "  ENDIF", "ENDIF", "B"});
    const std::pair<const char*, const char*> cases[] = {{"1 1", "BOTH X1 AND X2 > 0"},
                                                         {"1 0", "ONLY X1 GT 0"},
                                                         {"0 1", "ONLY X2 GT 0"},
                                                         {"0 0", "NEITHER X1 NOR X2 > 0"}};
    for (const auto& [values, expected] : cases) {
        type(std::string("X1=") + values[0] + "\r");
        type(std::string("X2=") + values[2] + "\r");
        EXPECT_EQ(type("RUN 55\r", 100ms), std::string("RUN 55\r\n") + expected + "\r\n-->") << values;
    }
}

TEST_F(Bds5Program, DwellTakesSimulatedTime) { // examples/bds5/39, L4491-4509
    download({"6$", "P \"BEGIN 5 SECOND DWELL\"", "D 5000", "P \"END 5 SECOND DWELL\"", "B"});
    EXPECT_EQ(type("RUN 6\r", 100ms), "RUN 6\r\nBEGIN 5 SECOND DWELL\r\n");
    EXPECT_EQ(type("", 4800ms), "") << "nothing before the 5 s are up";
    EXPECT_EQ(type("", 200ms), "END 5 SECOND DWELL\r\n-->");
}

TEST_F(Bds5Program, QuickIfAndTilCountALoop) {
    download({"1$", "X1=0", "2$", "X1=X1+1", "? X1 LT 20 GOTO 2 : P \"DONE \" X1[2]", "X2=0", "TIL X2 GE 5 X2=X2+1",
              "P X2[1]", "B"});
    EXPECT_EQ(type("RUN 1\r", 500ms), "RUN 1\r\nDONE 20\r\n5\r\n-->");
}

TEST_F(Bds5Program, ErrorInProgramNamesItsLine) { // L6069-6086: 11$ / PROP 2 / B
    download({"11$", "X1=1/0", "B"});
    const std::string out = type("RUN 11\r", 20ms);
    EXPECT_NE(out.find("\aERR 92 LINE 2 '1/0'"), std::string::npos) << out;
    EXPECT_TRUE(out.ends_with("ZERO DIVIDE\r\n-->")) << out;
}

TEST_F(Bds5Program, RunOfAMissingLabelIsErr70) {
    download({"1$", "B"});
    const std::string out = type("RUN 7\r");
    EXPECT_NE(out.find("\aERR 70 '7'"), std::string::npos) << out;
    EXPECT_TRUE(out.ends_with("LABEL NOT FOUND\r\n-->")) << out;
}

TEST_F(Bds5Program, LabelUsedTwiceIsReportedByRun) {
    download({"1$", "P \"A\"", "1$", "B"});
    const std::string out = type("RUN 1\r");
    EXPECT_NE(out.find("ERR 71 LINE 3 '1$'"), std::string::npos) << out;
}

TEST_F(Bds5Program, ErrorLabelMustBeLast) {
    download({"1$", "B", "ERROR$", "B", "2$", "B"});
    EXPECT_NE(type("RUN 1\r").find("ERR 74 LINE 5"), std::string::npos);
}

TEST_F(Bds5Program, GosubNestingLimitIsFour) {
    download({"1$", "GOSUB 1"});
    const std::string out = type("RUN 1\r", 50ms);
    EXPECT_NE(out.find("ERR 118 LINE 2"), std::string::npos) << out;
}

TEST_F(Bds5Program, ReturnWithoutGosub) {
    download({"1$", "RET"});
    EXPECT_NE(type("RUN 1\r", 20ms).find("ERR 119 LINE 2"), std::string::npos);
}

TEST_F(Bds5Program, EscapeEntersAndLeavesMonitorMode) { // L9757-9776
    download({"1$", "X1=X1+1", "D 10", "GOTO 1"});
    EXPECT_EQ(type("RUN 1\r", 20ms), "RUN 1\r\n");
    EXPECT_EQ(type("\x1b"), "\r\n\nENTER MONITOR MODE. PUSH ESCAPE TO EXIT\r\n==>");
    EXPECT_EQ(type("\r"), "\r\n==>");
    EXPECT_EQ(type("X2=7\r"), "X2=7\r\n==>");
    EXPECT_EQ(type("\x1b"), "\r\nENTER MONITOR MODE.");
    EXPECT_EQ(drive.mode(), Bds5DriveMode::Running);
    EXPECT_EQ(type("\r"), "") << "no prompt, no answer in run mode";
    type("\x1b");
    EXPECT_EQ(type("B\r"), "B\r\n-->"); // L9787-9790
    EXPECT_EQ(drive.mode(), Bds5DriveMode::Interactive);
    const std::string x1 = type("P X1\r");
    EXPECT_NE(x1, "P X1\r\n           0\r\n-->") << "the loop ran";
    EXPECT_EQ(type("P X2\r"), "P X2\r\n           7\r\n-->");
}

TEST_F(Bds5Program, MonitorRefusesCommandsOutsideItsSubset) { // L9800-9806
    download({"1$", "D 100000"});
    type("RUN 1\r", 5ms);
    type("\x1b");
    const std::string out = type("RUN\r");
    EXPECT_EQ(out.substr(0, 15), "RUN\r\n\r\n\n\aERR 63") << out;
    EXPECT_TRUE(out.ends_with("NOT AT THIS LEVEL\r\n==>")) << out;
}

TEST_F(Bds5Program, CtrlXBreaksARunningProgram) {
    download({"1$", "D 100000"});
    type("RUN 1\r", 5ms);
    EXPECT_EQ(type("\x18"), "-->");
    EXPECT_EQ(drive.mode(), Bds5DriveMode::Interactive);
}

TEST_F(Bds5Program, FaultWhileRunningPrintsAndBreaks) { // L9875-9884
    download({"6$", "D 100000"});
    type("RUN 6\r", 5ms);
    drive.raiseFault(17);
    EXPECT_EQ(wait(0ms), "\r\n\n\aERR 17 FEEDBACK LOSS\r\n-->");
}

TEST_F(Bds5Program, FaultInMonitorModeWaitsForCr) { // L9888-9935
    download({"6$", "D 100000"});
    type("RUN 6\r", 5ms);
    type("\x1b");
    drive.raiseFault(17);
    EXPECT_EQ(wait(0ms), "");
    EXPECT_EQ(type("\r"), "\r\n\n\aERR 17 FEEDBACK LOSS\r\n-->");
}

TEST_F(Bds5Program, CommandInMonitorModeWhileFaultWaitsIsIgnored) {
    download({"6$", "D 100000"});
    type("RUN 6\r", 5ms);
    type("\x1b");
    drive.raiseFault(17);
    EXPECT_EQ(type("P X1\r"), "P X1\r\nERROR MSG WAITING--COMMAND IGNORED\r\n\r\n\n\aERR 17 FEEDBACK LOSS\r\n-->");
}

TEST_F(Bds5Program, PowerUpLabelRunsAtPowerUp) { // L4929-4944, examples/bds5/48
    download({"POWER-UP$", "X1=X1+1", "B"});
    type("X1=0\r");
    drive.powerUp();
    const std::string out = wait(20ms);
    EXPECT_NE(out.find("EXECUTING POWER-UP LABEL\r\n"), std::string::npos) << out;
    EXPECT_TRUE(out.ends_with("-->")) << out;
    EXPECT_EQ(type("P X1\r"), "P X1\r\n           1\r\n-->");
}

TEST_F(Bds5Program, ProgramTooLargeIsErr86) {
    EXPECT_EQ(type(">BDS\r"), ">BDS\r\nl->");
    const std::string line(70, 'A');
    std::string last;
    for (int i = 0; i < 240; ++i) last = type("; " + line + "\r");
    EXPECT_NE(last.find("ERR 86"), std::string::npos) << last;
    type("\x1b");
}

TEST_F(Bds5Program, DumpListsProgramAndVariablesForResending) { // L5396-5414
    download({"1$", "B"});
    type("X1=111234\r");
    const std::string out = type("DUMP\r");
    EXPECT_EQ(out.find("DUMP\r\n;1$\r\n;B\r\n"), 0u) << out.substr(0, 80);
    EXPECT_NE(out.find("\r\nX1 111234\r\n"), std::string::npos);
    EXPECT_NE(out.find("\r\nBAUD 9600\r\n"), std::string::npos);
    EXPECT_NE(out.find("\r\n;VMAX 7500\r\n"), std::string::npos) << "protected: prefixed with ;";
    EXPECT_TRUE(out.ends_with("\r\n-->"));
    // Re-sending every line of the dump is harmless: no line draws an error.
    std::size_t start = out.find("\r\n") + 2;
    int errors = 0;
    for (std::size_t end; (end = out.find("\r\n", start)) != std::string::npos; start = end + 2) {
        const std::string line = out.substr(start, end - start);
        if (line.empty() || line == "-->") continue;
        const std::string answer = type(line + "\r");
        if (answer.find("\aERR") != std::string::npos) {
            ++errors;
            ADD_FAILURE() << line << " -> " << answer;
        }
    }
    EXPECT_EQ(errors, 0);
}

TEST_F(Bds5Program, DumpNeedsTheDriveDisabled) {
    type("EN\r");
    EXPECT_NE(type("DUMP\r").find("\aERR 51 'DUMP'"), std::string::npos);
    EXPECT_EQ(type("DUMP VERSION\r"), "DUMP VERSION\r\nBDS5 FIRMWARE V3.0.0 (SERVODESK SIMULATION)\r\n-->");
}

TEST_F(Bds5Program, EscapeStopsAListing) {
    drive.receive("DUMP\r");
    for (int i = 0; i < 100; ++i) drive.step(1ms);
    drive.takeTransmitted();
    EXPECT_TRUE(drive.transmitting());
    const std::string rest = type("\x1b");
    EXPECT_TRUE(rest.ends_with("\r\n-->")) << rest;
    EXPECT_LT(rest.size(), 200u) << "the rest of the dump was dropped";
}

TEST_F(Bds5Program, PowerLostWhileLoadingCorruptsTheProgram) { // L3712, L3746, L7513
    download({"1$", "P \"OK\"", "B"});
    type(">BDS\r");
    type("1$\r");
    drive.powerUp(); // power fails in the middle of the download
    const std::string signOn = wait(100ms);
    EXPECT_NE(signOn.find("\aERR 202 USER PROGRAM CORRUPT\r\n-->"), std::string::npos) << signOn;
    EXPECT_NE(type("RUN 1\r").find("\aERR 202 'RUN'"), std::string::npos);
    download({"1$", "P \"OK\"", "B"});
    EXPECT_EQ(type("RUN 1\r", 20ms), "RUN 1\r\nOK\r\n-->") << ">BDS clears the corruption";
}
