// The 26 example files of the PMC-960 manual (spec/examples/pmc960, digest §8): each runs on the simulated
// controller with the outcome §8's table gives. The files keep the OCR damage; the commands sent here are
// the de-escaped ones the table lists (T1Y1 placeholders become concrete ticks and counts).
#include "pmc960_test_drive.h"

#include <filesystem>

namespace pmc960_test {
namespace {

using drive_core::pmc960::Pmc960Line;

TEST(Pmc960Examples, AllTwentySixFilesArePresent) {
    int count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(PMC960_EXAMPLES_DIR))
        if (entry.path().extension() == ".mpl") ++count;
    EXPECT_EQ(count, 26);
}

TEST(Pmc960Examples, Ex01LabelComments) {
    TestDrive t;
    t.load("@.This_is_a_comment_line\r@X_Comment_after_a_program_label_'X'\r");
    t.type("BX\r");
    EXPECT_EQ(t.type("SB?"), prompted("SB?X 0"));
    EXPECT_EQ(t.type("B.\r", 10ms), prompted("B.")); // runs through both lines to the end of the buffer
}

TEST(Pmc960Examples, Ex02Acceleration) {
    TestDrive t;
    t.type("A3500\r");
    EXPECT_EQ(t.type("A?"), prompted("A?3500"));
    EXPECT_EQ(t.type("A!"), prompted("A!0"));
}

TEST(Pmc960Examples, Ex03BranchConditional) {
    TestDrive t;
    t.load("@Q\rOB1:1\r");
    t.type("BQ1:1\r");
    EXPECT_EQ(t.drive.state().reg.outputs, 0); // IN00' inactive: no branch
    t.drive.setInput(1, true);
    t.type("BQ1:1\r");
    EXPECT_EQ(t.drive.state().reg.outputs, 1);
}

TEST(Pmc960Examples, Ex04Cam) { // L1116-1117: 100 RPM by position 1000, then on to 2000 at that speed
    TestDrive t;
    t.enable();
    const auto& motion = t.drive.state().motion;
    EXPECT_EQ(t.type("C1000:100\r"), prompted("C1000:100"));
    EXPECT_EQ(t.type("C2000^"), "C2000^"); // ^: the prompt once this segment has reached 2000
    double speedAt1000 = -1;
    std::string out;
    for (int ms = 0; ms < 1000 && out.empty(); ++ms) {
        if (speedAt1000 < 0 && motion.commanded_counts() >= 1000) speedAt1000 = motion.referenceVelocity_cps();
        out = t.wait(1ms);
    }
    EXPECT_EQ(out, kPrompt);
    EXPECT_NEAR(speedAt1000, 10000, 10000 * 0.001 + 40); // V 100 = 10,000 counts/s (within one 1 ms tick)
    EXPECT_NEAR(motion.commanded_counts(), 2000, 10 + 1);
    EXPECT_EQ(t.type("V!"), prompted("V!100")); // the cam holds its speed past 2000
    EXPECT_EQ(t.type("C3000:0^", 300ms), prompted("C3000:0^"));
    EXPECT_FALSE(motion.moving());
    EXPECT_EQ(t.type("G!"), prompted("G!3000"));
}

TEST(Pmc960Examples, Ex05Dwell) {
    TestDrive t;
    t.enable();
    t.type("I1000+\r");
    EXPECT_EQ(t.type("D24,"), "D24,");
    const std::string out = t.wait(100ms);
    EXPECT_EQ(out, "}");
    EXPECT_EQ(t.type("\r"), "");
    EXPECT_EQ(t.wait(30ms), kPrompt);
}

TEST(Pmc960Examples, Ex05DwellAfterTopSpeed) { // D300;<cr>: 300 ms after top speed
    TestDrive t;
    t.enable();
    t.type("I100000+\r"); // 10 ms to V400 at A4000
    EXPECT_EQ(t.type("D300;"), "D300;");
    EXPECT_EQ(t.wait(5ms), ""); // still accelerating
    std::string handshake;
    for (int ms = 0; ms < 20 && handshake.empty(); ++ms) handshake = t.wait(1ms);
    EXPECT_EQ(handshake, "}");
    EXPECT_EQ(t.drive.state().motionBits() & 0x0C, 0x0C); // MOTION, TOP VELOCITY
    EXPECT_EQ(t.type("\r"), "");                          // the dwell starts now
    EXPECT_EQ(t.wait(299ms), "");
    EXPECT_EQ(t.wait(8ms), kPrompt); // on the 4 ms clock: 300 to 304 ms
}

TEST(Pmc960Examples, Ex06And07CallAndExit) {
    TestDrive t;
    t.load("@M\rFA\rOB2:2\rQ\r@A\rOB1:1\rE8:8\rOB4:4\rE\r");
    t.type("BM\r");
    EXPECT_EQ(t.drive.state().reg.outputs, 7);
}

TEST(Pmc960Examples, Ex08Go) {
    TestDrive t;
    t.enable();
    t.type("G400+\r");
    t.wait(300ms);
    EXPECT_EQ(t.type("G!"), prompted("G!400"));
    EXPECT_EQ(t.type("G+\r"), prompted("G+"));
    t.wait(300ms);
    EXPECT_EQ(t.type("G%\r"), "G%\r\n0");
    EXPECT_EQ(t.type("\r"), kPrompt);
}

TEST(Pmc960Examples, Ex09HomeResolver) {
    TestDrive t;
    t.enable();
    t.type("H15+\r");
    t.wait(500ms);
    EXPECT_EQ(t.type("H!"), prompted("H!15"));
    EXPECT_EQ(t.type("H,-\r"), prompted("H,}-"));
    t.wait(3000ms);
    EXPECT_EQ(t.type("G!"), prompted("G!-4081"));
    EXPECT_EQ(t.type("H*"), prompted("H*")); // L1216: H* with no <cr> is a whole command
}

TEST(Pmc960Examples, Ex10HomeEncoder) {
    TestDrive t;
    t.writeEnable();
    t.type("THA0\r");
    t.enable();
    EXPECT_EQ(t.type("H+"), prompted("H+")); // H[<sync>]<direction>: no <cr> with an encoder (L1222)
    t.wait(3000ms);
    EXPECT_EQ(t.type("G!"), prompted("G!4096")); // the marker
    EXPECT_EQ(t.type("H,-"), prompted("H,}-"));
    t.wait(300ms);
    EXPECT_EQ(t.type("H*"), prompted("H*"));
    t.wait(100ms);
    EXPECT_FALSE(t.drive.state().motion.moving());
}

TEST(Pmc960Examples, Ex11Index) {
    TestDrive t;
    t.enable();
    t.type("I250\r");
    t.type("I+\r");
    t.wait(50ms);
    EXPECT_EQ(t.type("I,-\r"), prompted("I,}-"));
    t.wait(300ms);
    EXPECT_EQ(t.type("G!"), prompted("G!0"));
    EXPECT_EQ(t.type("I?"), prompted("I?250"));
    EXPECT_EQ(t.type("I!"), prompted("I!0"));
    EXPECT_EQ(t.type("I%200\r"), "I%200\r\n0");
    EXPECT_EQ(t.type("\r"), kPrompt);
}

TEST(Pmc960Examples, Ex12Jog) {
    TestDrive t;
    t.enable();
    EXPECT_EQ(t.type("J?"), prompted("J?100"));
    t.type("J+\r");
    t.wait(10ms);
    EXPECT_EQ(t.type("J!"), prompted("J!100"));
    t.type("J*\r");
    EXPECT_EQ(t.type("J,-\r"), "J,");
    EXPECT_EQ(t.wait(20ms), "}");
}

TEST(Pmc960Examples, Ex13LoopProgramT) {
    TestDrive t;
    t.load("@T\rI+,\rLT9\rE\r");
    t.enable();
    t.type("I1\r");
    t.type("BT\r");
    t.wait(1000ms);
    EXPECT_EQ(t.type("G!"), prompted("G!10"));
    t.type("LT999\r");
    EXPECT_EQ(t.wait(30000ms), kPrompt);
    EXPECT_EQ(t.type("G!"), prompted("G!1010"));
}

TEST(Pmc960Examples, Ex14LoopResetProgramGW) {
    TestDrive t;
    t.load("@G\rI+,\rBW1\rLG2999\r@W\rI,-\rLW19\r");
    t.enable();
    t.type("I1\r");
    t.type("V1920\r");
    t.type("A65535\r");
    t.type("LG4\r"); // 5 indexes forward, then fall through into W: 20 back
    EXPECT_EQ(t.wait(5000ms), kPrompt);
    EXPECT_EQ(t.type("G!"), prompted("G!-15"));
}

TEST(Pmc960Examples, Ex15LoopExamples) {
    TestDrive t;
    t.load("@B\rOB1:1\rLB20\rOB2:2\rLBX20\r");
    EXPECT_EQ(t.type("BB\r", 1000ms), "BB" + std::string(kPrompt));
    EXPECT_EQ(t.drive.state().reg.outputs, 3);
}

TEST(Pmc960Examples, Ex16Normalize) {
    TestDrive t;
    EXPECT_EQ(t.type("N2000,+"), prompted("N2000,}+"));
    EXPECT_EQ(t.type("G!"), prompted("G!2000"));
    EXPECT_EQ(t.type("N*"), prompted("N*"));
    EXPECT_EQ(t.type("G!"), prompted("G!0"));
    EXPECT_EQ(t.type("N\r"), prompted("N\r\nPMC-960 MPL (SERVODESK SIMULATION)"));
}

TEST(Pmc960Examples, Ex17OutputBinary) {
    TestDrive t;
    t.type("OBC\r");
    t.type("OBC:C\r");
    EXPECT_EQ(t.type("OB?"), prompted("OB?000C"));
}

TEST(Pmc960Examples, Ex18ProgramCommand) {
    TestDrive t;
    t.load("@A\rI+\r");
    EXPECT_EQ(t.type("P?"), "P?\r\n@A");
    EXPECT_EQ(t.type("\n"), "\r\nI+");
    EXPECT_EQ(t.type("\x1b"), kPrompt);
    t.type("P\r");
    t.type("@B\r");
    t.type("\x1b");
    EXPECT_EQ(t.drive.state().program.text(), "@A\rI+\r@B\r");
}

TEST(Pmc960Examples, Ex19SoftwareLimits) {
    TestDrive t;
    t.type("s1f10000\r"); // the OCR's s1 is no command: #A1, then the rest is read as commands
    t.type("slf10000\r");
    t.type("slr5000-\r");
    EXPECT_EQ(t.type("SL?"), prompted("SL?F10000 R-5000"));
}

TEST(Pmc960Examples, Ex20TableGains) {
    TestDrive t;
    t.writeEnable();
    for (const char* line : {"TGP17\r", "TGV34\r", "TGP++V5--\r", "TGE0\r", "TGB4\r"}) t.type(line);
    EXPECT_EQ(t.type("TG?"), prompted("TG?\r\nP-19 V-24 T-160 F-16 E-00 B-04 X-0 L-0"));
}

TEST(Pmc960Examples, Ex21And22BinaryInput) {
    TestDrive t;
    t.writeEnable();
    t.type("THCC0\r");
    t.type(std::string("v\0\x03\x78", 4));
    t.type(std::string("i\0\0\0\x1d\x1d\x4c", 7)); // "total of 7 bytes sent" (L1894)
    EXPECT_EQ(t.drive.state().reg.velocity, 888);
    EXPECT_EQ(t.drive.state().reg.distance, 7500);
}

TEST(Pmc960Examples, Ex23And24ContourHandshakes) {
    TestDrive t;
    t.enable();
    EXPECT_EQ(t.type("R"), "R}");
    EXPECT_EQ(t.type("1C0"), "1C0}");  // T1Y1: +192 counts in 1.33 ms; next accepted at once
    EXPECT_EQ(t.type("3200"), "3200"); // T2Y2 waits until segment 1 runs out (point A)
    std::string handshake;             // point A: segment 1 has run out, segment 2 runs
    for (int ms = 0; ms < 50 && handshake.empty(); ++ms) handshake = t.wait(1ms);
    EXPECT_EQ(handshake, "}");
    // T3Y3 (+768 counts): no } until segment 2 ends at point B (192 + 512 counts).
    EXPECT_EQ(t.type("3300"), "3300");
    handshake.clear();
    for (int ms = 0; ms < 50 && handshake.empty(); ++ms) {
        EXPECT_LT(t.drive.state().motion.commanded_counts(), 704);
        handshake = t.wait(1ms);
    }
    EXPECT_EQ(handshake, "}");
    EXPECT_GE(t.drive.state().motion.commanded_counts(), 704);
    EXPECT_EQ(t.type("0\r"), prompted("0"));
    t.wait(300ms);
    EXPECT_EQ(t.type("G!"), prompted("G!1472"));
}

TEST(Pmc960Examples, Ex25ContourSeparateLines) { // L2239-2247
    TestDrive t;
    t.enable();
    EXPECT_EQ(t.type("R1C0\r"), prompted("R}1C0}"));
    EXPECT_EQ(t.type("R3200\r"), prompted("R}3200")); // <cr> before point A: no } for this segment
    EXPECT_EQ(t.type("R"), "R");                      // the } after R waits for the running segment
    EXPECT_EQ(t.wait(50ms), "}");
    EXPECT_EQ(t.type("3200\r"), prompted("3200}"));
}

TEST(Pmc960Examples, Ex26ContourSensorStart) { // L2255-2264: the first segment waits for SENSOR
    TestDrive t;
    t.enable();
    EXPECT_EQ(t.type("SY30\r"), prompted("SY30")); // SY read as SP (digest §11.2 #20)
    EXPECT_EQ(t.type("SP?"), prompted("SP?30"));
    // R T1Y1 T2Y2<cr>: +192 counts, then +512; the second is queued behind the held first.
    EXPECT_EQ(t.type("R1C03200\r"), prompted("R}1C0}3200"));
    EXPECT_EQ(t.type("SY0\r", 100ms), prompted("SY0"));
    EXPECT_EQ(t.type("G!"), prompted("G!0")); // no SENSOR yet: nothing has moved
    EXPECT_EQ(t.type("R"), "R");              // both segments still to run: no } for T3Y3
    EXPECT_EQ(t.wait(100ms), "");
    t.drive.setLine(Pmc960Line::Sensor, true); // segment 1 starts; segment 2 follows without SENSOR
    std::string handshake;                     // the } once segment 1 has run out and segment 2 runs
    for (int ms = 0; ms < 50 && handshake.empty(); ++ms) handshake = t.wait(1ms);
    EXPECT_EQ(handshake, "}");
    EXPECT_TRUE(t.drive.state().motion.moving());
    EXPECT_EQ(t.type("3200\r"), prompted("3200")); // T3Y3 waits behind segment 2: no } for it
    EXPECT_TRUE(t.drive.state().motion.full());
    t.drive.setLine(Pmc960Line::Sensor, false);
    t.wait(300ms);
    EXPECT_EQ(t.type("G!"), prompted("G!1216"));
}

TEST(Pmc960Examples, ErrorsFromTheBreakMatrix) { // 5.3.5: FAULT' #E3, BREAK' #C7
    TestDrive t;
    t.load("@A\rBA\r");
    t.type("BA\r");
    t.drive.setLine(Pmc960Line::Break, true);
    EXPECT_EQ(t.drive.takeTransmitted(), "#C7" + std::string(kPrompt));
    t.drive.setLine(Pmc960Line::Fault, true);
    EXPECT_EQ(t.drive.takeTransmitted(), "#E3" + std::string(kPrompt));
}

} // namespace
} // namespace pmc960_test
