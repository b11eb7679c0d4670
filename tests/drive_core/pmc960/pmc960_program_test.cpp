// The PMC-960 program buffer and execution: the P-mode editor, labels with fall-through, F/E calls, the
// X/Y/Z loop counters, conditions on IN07'-IN00', single-step and trace — examples 01, 03, 06, 07, 13-15, 18.
#include "pmc960_test_drive.h"

#include "drive_core/catalog/pmc960_catalog.h"

namespace pmc960_test {
namespace {

TEST(Pmc960Program, EditorAppendsAndListsTheBuffer) { // example 18, L1416-1418
    TestDrive t;
    t.load("@.This_is_a_comment_line\r@XI+\r");
    EXPECT_EQ(t.drive.state().program.text(), "@.This_is_a_comment_line\r@XI+\r");
    EXPECT_EQ(t.type("P!"), prompted("P!\r\n@.This_is_a_comment_line\r\n@XI+"));
    EXPECT_EQ(t.type("P?"), "P?\r\n@.This_is_a_comment_line");
    EXPECT_EQ(t.type("\n"), "\r\n@XI+");
    EXPECT_EQ(t.type("\n"), kPrompt);
}

TEST(Pmc960Program, EditorNeedsWriteEnable) {
    TestDrive t;
    EXPECT_EQ(t.type("P{"), prompted("P{#D3"));
}

TEST(Pmc960Program, EditorOvertypesInsertsAndKills) {
    TestDrive t;
    t.load("@AI+\rQ\r");
    t.type("PA");      // at @A
    t.type("\t\t\tX"); // over '+'
    t.type("\x1b");
    EXPECT_EQ(t.drive.state().program.text(), "@AIX\rQ\r");
    t.type("PA");
    t.type("\t\t\x16V5\r\x16\x1b"); // Ctrl-V insert before I
    EXPECT_EQ(t.drive.state().program.text(), "@AV5\rIX\rQ\r");
    t.type("PA");
    t.type("\x0b\x1b"); // Ctrl-K: kill to end of line
    EXPECT_EQ(t.drive.state().program.text(), "\rIX\rQ\r");
}

TEST(Pmc960Program, BufferFullIsC1) {
    TestDrive t;
    t.writeEnable();
    t.type("P\r");
    const std::string out = t.type(std::string(1945, 'A'));
    EXPECT_NE(out.find("#C1"), std::string::npos);
    EXPECT_EQ(t.drive.state().program.size(), 1940u);
}

TEST(Pmc960Program, LoopRunsTenIndexes) { // example 13, L1317-1323: BT -> 10 indexes
    TestDrive t;
    t.load("@T\rI+,\rLT9\rE\r");
    t.enable();
    t.type("I100\r");
    EXPECT_EQ(t.type("BT\r"), "BT");
    EXPECT_EQ(t.wait(3000ms), kPrompt);
    EXPECT_EQ(t.type("G!"), prompted("G!1000"));
}

TEST(Pmc960Program, InteractiveLoopCountOverride) { // L1323: LT999 -> 1000 indexes
    TestDrive t;
    t.load("@T\rI+,\rLT9\rE\r");
    t.enable();
    t.type("I10\r");
    t.type("V1920\r");
    t.type("LT99\r"); // 100 indexes
    EXPECT_EQ(t.wait(10000ms), kPrompt);
    EXPECT_EQ(t.type("G!"), prompted("G!1000"));
}

TEST(Pmc960Program, BranchOutOfLoopFallsThroughLabels) { // example 14, L1328-1337
    TestDrive t;
    t.load("@G\rI+,\rBW1\rLG2999\r@W\rI,-\rLW19\r");
    t.enable();
    t.type("I10\r");
    t.drive.setInput(1, true); // IN00' asserted: BW1 holds at once
    t.type("BG\r");
    t.wait(5000ms);
    // 1 forward index, then W: 20 reverse indexes
    EXPECT_EQ(t.type("G!"), prompted("G!-190"));
}

TEST(Pmc960Program, ConditionalBranchUsesMask) { // example 03, L1087-1091
    TestDrive t;
    t.load("@Q\rOB1\r");
    t.type("BQ10:F0\r");
    EXPECT_EQ(t.drive.state().reg.outputs, 0);
    t.drive.setInput(5, true); // IN04'
    t.drive.setInput(1, true); // IN00' is masked out
    t.type("BQ10:F0\r");
    t.wait(5ms);
    EXPECT_EQ(t.drive.state().reg.outputs, 1);
}

TEST(Pmc960Program, FunctionCallAndExit) { // examples 06, 07
    TestDrive t;
    t.load("@M\rFA\rOB2:2\rQ\r@A\rOB1:1\rE8:8\rOB4:4\rE\r");
    t.type("BM\r");
    t.wait(5ms);
    EXPECT_EQ(t.drive.state().reg.outputs, 7);
    t.type("OB0\r");
    t.drive.setInput(4, true); // IN03': E8:8 returns early
    t.type("BM\r");
    t.wait(5ms);
    EXPECT_EQ(t.drive.state().reg.outputs, 3);
}

TEST(Pmc960Program, UndefinedLabelIsC2) {
    TestDrive t;
    EXPECT_EQ(t.type("BZ\r"), prompted("BZ#C2"));
    EXPECT_EQ(t.type("LQX5\r"), prompted("LQX5#C2"));
    EXPECT_EQ(t.type("LQW"), prompted("LQW#C8"));
}

TEST(Pmc960Program, LastLabelAndCommandCount) { // SB, L1466-1474
    TestDrive t;
    t.load("@.comment\r@X\rOB1\rOB2\rQ\r");
    t.type("B.\r");
    t.wait(5ms);
    EXPECT_EQ(t.type("SB?"), prompted("SB?X 2"));
}

TEST(Pmc960Program, EscapeDuringProgramIsC4) {
    TestDrive t;
    t.load("@A\rD1000\rBA\r");
    t.type("BA\r");
    t.wait(10ms);
    EXPECT_EQ(t.type("\x1b"), "#D0" + std::string(kPrompt)); // it was dwelling
    t.load("@B\rOB1\rBB\r");
    t.type("BB\r");
    t.wait(10ms);
    EXPECT_EQ(t.type("\x1b"), "#C4" + std::string(kPrompt));
}

TEST(Pmc960Program, SingleStepWaitsAtEachLabel) { // THC bit 2, L1856
    TestDrive t;
    t.load("@A\rOB1\r@B\rOB2\r");
    t.type("THC4\r");
    t.type("BA\r");
    t.wait(5ms);
    EXPECT_EQ(t.drive.state().reg.outputs, 0);
    t.type("@");
    t.wait(5ms);
    EXPECT_EQ(t.drive.state().reg.outputs, 1);
    EXPECT_EQ(t.type("@"), kPrompt);
    EXPECT_EQ(t.drive.state().reg.outputs, 2);
}

TEST(Pmc960Program, TraceShowsCommandsAsTheyRun) { // THC bit 1
    TestDrive t;
    t.load("@A\rOB1\r");
    t.type("THC2\r");
    EXPECT_EQ(t.type("BA\r"), "BA@A\r\nOB1\r\n" + std::string(kPrompt));
}

TEST(Pmc960Program, PowerUpRoutineRuns) { // TLP, L2016-2033
    TestDrive t;
    t.load("@Z\rOB5\r");
    t.type("TLPZ\r");
    t.drive.powerUp();
    t.wait(5ms);
    EXPECT_EQ(t.drive.state().reg.outputs, 5);
}

TEST(Pmc960Program, StartLineRunsAddressedRoutine) { // START' + ADDR, L932-976
    TestDrive t;
    t.load("@C\rOB3\r");
    t.drive.setAddress(3);
    t.drive.setLine(drive_core::pmc960::Pmc960Line::Start, true);
    t.wait(5ms);
    EXPECT_EQ(t.drive.state().reg.outputs, 3);
}

TEST(Pmc960Catalog, HasEveryErrorAndCommandForm) {
    namespace cat = drive_core::catalog::pmc960;
    EXPECT_EQ(cat::errors().size(), 65u);
    EXPECT_EQ(cat::commands().size(), 60u);
    ASSERT_NE(cat::findError(0xE1), nullptr);
    EXPECT_TRUE(cat::findError(0xE1)->asynchronous);
    EXPECT_EQ(cat::findError(0xB5)->message, "ESC during synchronization");
    EXPECT_EQ(cat::findCommand("TGP")->longName, "POSITION LOOP GAIN");
    EXPECT_EQ(cat::findParameter("SF")->factory, 2048);
}

} // namespace
} // namespace pmc960_test
