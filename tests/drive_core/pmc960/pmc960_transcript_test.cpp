// Transcripts of the PMC-960 manual's interactive examples: the bytes a user types and, byte for byte, what
// the controller sends back (echo, values, #xx errors, the CR LF <axis> } prompt, the } sync handshake).
#include "pmc960_test_drive.h"

#include <cstdlib>

namespace pmc960_test {
namespace {

TEST(Pmc960Transcript, PowerUpSendsThePrompt) {
    drive_core::pmc960::Pmc960Drive drive;
    drive.setLineRateLimited(false);
    drive.powerUp();
    EXPECT_EQ(drive.takeTransmitted(), "\r\n=}");
}

TEST(Pmc960Transcript, AccelerationSetAndDisplayed) { // example 02, L1071-1073
    TestDrive t;
    EXPECT_EQ(t.type("A3500\r"), prompted("A3500"));
    EXPECT_EQ(t.type("A?"), prompted("A?3500"));
    EXPECT_EQ(t.type("A!"), prompted("A!0")); // 0 at rest
}

TEST(Pmc960Transcript, EmptyLineIsJustAPrompt) {
    TestDrive t;
    EXPECT_EQ(t.type("\r"), kPrompt);
    EXPECT_EQ(t.type("  \r"), "  " + std::string(kPrompt));
}

TEST(Pmc960Transcript, InvalidCommandIsA1) {
    TestDrive t;
    EXPECT_EQ(t.type("W"), prompted("W#A1"));
    EXPECT_EQ(t.drive.state().reg.lastError, 0xA1);
    EXPECT_EQ(t.type("SE?"), prompted("SE?A1"));
}

TEST(Pmc960Transcript, RangeErrorsCarryTheirCodes) {
    TestDrive t;
    EXPECT_EQ(t.type("A0\r"), prompted("A0#92"));
    EXPECT_EQ(t.type("V5000\r"), prompted("V5000#94")); // 192 kHz range: 1-1920
    EXPECT_EQ(t.type("SW2\r"), prompted("SW2#95"));
    EXPECT_EQ(t.type("SM4\r"), prompted("SM4#90"));
    EXPECT_EQ(t.type("AX"), prompted("AX#A2"));
}

TEST(Pmc960Transcript, OutputsWithMask) { // example 17, L1394-1396
    TestDrive t;
    EXPECT_EQ(t.type("OBC\r"), prompted("OBC"));
    EXPECT_EQ(t.type("OB?"), prompted("OB?000C"));
    EXPECT_TRUE(t.drive.output(3)); // OUT02'
    EXPECT_TRUE(t.drive.output(4)); // OUT03'
    EXPECT_EQ(t.type("OBFF00\r"), prompted("OBFF00"));
    EXPECT_EQ(t.type("OBC:C\r"), prompted("OBC:C"));
    EXPECT_EQ(t.type("OB?"), prompted("OB?FF0C"));
}

TEST(Pmc960Transcript, SoftwareLimits) { // example 19, L1551-1553 (OCR s1 = SL)
    TestDrive t;
    EXPECT_EQ(t.type("slf10000\r"), prompted("slf10000"));
    EXPECT_EQ(t.type("SLR5000-\r"), prompted("SLR5000-"));
    EXPECT_EQ(t.type("SL?"), prompted("SL?F10000 R-5000"));
}

TEST(Pmc960Transcript, TableGainsNeedWriteEnable) { // example 20, L1769-1773
    TestDrive t;
    EXPECT_EQ(t.type("TGP17\r"), prompted("TGP17#D3"));
    t.writeEnable();
    EXPECT_EQ(t.type("TGP17\r"), prompted("TGP17"));
    EXPECT_EQ(t.type("TGV34\r"), prompted("TGV34"));
    EXPECT_EQ(t.type("TGP++V5--\r"), prompted("TGP++V5--"));
    EXPECT_EQ(t.drive.state().table.stored("TGP"), 19);
    EXPECT_EQ(t.drive.state().table.stored("TGV"), 24);
    EXPECT_EQ(t.type("TGE0\r"), prompted("TGE0"));
    EXPECT_EQ(t.type("TGB1F\r"), prompted("TGB1F")); // compensators are entered in hex
    EXPECT_EQ(t.type("TG?"), prompted("TG?\r\nP-19 V-24 T-160 F-16 E-00 B-1F X-0 L-0"));
    EXPECT_EQ(t.type("TGP?"), prompted("TGP?\r\nP-19"));
    EXPECT_EQ(t.type("TGP300\r"), prompted("TGP300#90"));
}

TEST(Pmc960Transcript, FeedForwardTable) { // TF, L1721-1739
    TestDrive t;
    t.writeEnable();
    EXPECT_EQ(t.type("TGF100\r"), prompted("TGF100"));
    EXPECT_EQ(t.type("TF?"), prompted("TF?\r\n48-25 192-100 384-200 Ext-100"));
    EXPECT_EQ(t.type("TGF200\r"), prompted("TGF200#9C"));
}

TEST(Pmc960Transcript, UnitsAreFixedPoint) { // TUA/TUP/TUS with ':' (L2050-2115)
    TestDrive t;
    t.writeEnable();
    EXPECT_EQ(t.type("TUS68:27\r"), prompted("TUS68:27"));
    EXPECT_EQ(t.type("TUS?"), prompted("TUS?\r\nS-68:27"));
    EXPECT_EQ(t.type("TUA5:7:"), prompted("TUA5:7:#AA"));
    EXPECT_EQ(t.type("TUP70000\r"), prompted("TUP70000#97"));
    EXPECT_EQ(t.type("TUV9000\r"), prompted("TUV9000#D4")); // 68.27 x 9000 > 384000
}

TEST(Pmc960Transcript, MotionNeedsTheDriveEnabled) {
    TestDrive t;
    EXPECT_EQ(t.type("I100+"), prompted("I100+#B6"));
    t.enable();
    EXPECT_EQ(t.type("I100+\r"), prompted("I100+"));
    t.wait(100ms);
    EXPECT_EQ(t.type("G!"), prompted("G!100"));
    EXPECT_EQ(t.type("I?"), prompted("I?100"));
}

TEST(Pmc960Transcript, IndexWithSyncsOnOneLine) { // example 11, L1260: I,+,- and the } handshakes
    TestDrive t;
    t.enable();
    EXPECT_EQ(t.type("I250\r"), prompted("I250"));
    EXPECT_EQ(t.type("I,+"), "I,}+"); // at rest: the , is satisfied at once
    EXPECT_EQ(t.type(","), ",");      // waits for the index to finish
    EXPECT_EQ(t.wait(200ms), "}");
    EXPECT_EQ(t.type("-\r"), prompted("-"));
    t.wait(200ms);
    EXPECT_EQ(t.type("G!"), prompted("G!0"));
}

TEST(Pmc960Transcript, CharactersSentDuringASyncWaitAreLost) { // L2535
    TestDrive t;
    t.enable();
    EXPECT_EQ(t.type("I1000+,A5\r"), "I1000+,");
    EXPECT_EQ(t.wait(300ms), "}");
    EXPECT_EQ(t.type("\r"), kPrompt);
    EXPECT_EQ(t.type("A?"), prompted("A?4000")); // A5 never arrived
}

TEST(Pmc960Transcript, JogSyncAtSpeed) { // tech note L2533: "J100+;" -> } at constant speed
    TestDrive t;
    t.enable();
    EXPECT_EQ(t.type("J100+;"), "J100+;");
    EXPECT_EQ(t.wait(10ms), "}"); // 10 kHz at 4,000 kHz/s: 2.5 ms
    EXPECT_EQ(t.type("\r"), kPrompt);
    EXPECT_EQ(t.type("J!"), prompted("J!100")); // the reference
    t.wait(100ms);                              // the motor settles on it
    EXPECT_EQ(t.type("V!"), prompted("V!100"));
}

TEST(Pmc960Transcript, JogReversals) { // example 12, L1289-1296: J,-*+*-
    TestDrive t;
    t.enable();
    EXPECT_EQ(t.type("J,-"), "J,}-");
    t.wait(20ms);
    EXPECT_EQ(t.type("*"), "*");
    t.wait(20ms);
    EXPECT_EQ(t.type("+*-\r"), prompted("+*-"));
    t.wait(20ms);
    EXPECT_EQ(t.type("J!"), prompted("J!100"));
    EXPECT_LT(t.drive.state().motion.velocity_cps(), 0);
    EXPECT_EQ(t.type("J*\r"), prompted("J*"));
    t.wait(20ms);
    EXPECT_FALSE(t.drive.state().motion.moving());
}

TEST(Pmc960Transcript, JogStopsOnAnyOtherCharacter) { // L1270
    TestDrive t;
    t.enable();
    t.type("J+");
    t.wait(10ms);
    EXPECT_EQ(t.type("Z"), prompted("Z#A2"));
    t.wait(20ms);
    EXPECT_FALSE(t.drive.state().motion.moving());
}

TEST(Pmc960Transcript, MotionWhileMovingIsB2) {
    TestDrive t;
    t.enable();
    t.type("I100000+\r");
    EXPECT_EQ(t.type("G0+"), prompted("G0+#B2"));
}

TEST(Pmc960Transcript, GoAndNormalize) { // examples 08 and 16, L1187-1189, L1361-1363
    TestDrive t;
    t.enable();
    EXPECT_EQ(t.type("G500-\r"), prompted("G500-"));
    t.wait(200ms);
    EXPECT_EQ(t.type("G!"), prompted("G!-500"));
    EXPECT_EQ(t.type("G?"), prompted("G?-500"));
    EXPECT_EQ(t.type("N2000,+"), prompted("N2000,}+"));
    EXPECT_EQ(t.type("G!"), prompted("G!2000"));
    EXPECT_EQ(t.type("G+\r"), prompted("G+"));
    t.wait(200ms);
    EXPECT_EQ(t.type("G!"), prompted("G!0"));
}

TEST(Pmc960Transcript, NCrPrintsTheFirmwareIdentifier) {
    TestDrive t;
    EXPECT_EQ(t.type("N\r"), prompted("N\r\nPMC-960 MPL (SERVODESK SIMULATION)"));
}

TEST(Pmc960Transcript, HomeToResolverLocation) { // example 09, L1214-1216
    TestDrive t;
    t.enable();
    EXPECT_EQ(t.type("H15+\r"), prompted("H15+"));
    t.wait(500ms);
    EXPECT_EQ(t.type("H!"), prompted("H!15"));
    EXPECT_EQ(t.type("H?"), prompted("H?15"));
    EXPECT_EQ(t.type("H5000+"), prompted("H5000+#9B")); // THA 4096
}

TEST(Pmc960Transcript, DwellLastsOnTheFourMillisecondClock) { // example 05, L1132-1134
    TestDrive t;
    EXPECT_EQ(t.type("D16\r"), "D16");
    EXPECT_EQ(t.wait(15ms), "");
    EXPECT_EQ(t.wait(10ms), kPrompt);
    EXPECT_EQ(t.type("D0\r"), prompted("D0"));
}

TEST(Pmc960Transcript, EscapeAbortsWaitsWithTheirCodes) { // L2350, L2369, L2375
    TestDrive t;
    t.enable();
    t.type("J+\r");
    EXPECT_EQ(t.type("J,"), "J,");
    EXPECT_EQ(t.type("\x1b"), "#B5" + std::string(kPrompt));
    EXPECT_EQ(t.type("D1000\r"), "D1000");
    EXPECT_EQ(t.type("\x1b"), "#D0" + std::string(kPrompt));
    EXPECT_EQ(t.type("U1\r"), "U1");
    EXPECT_EQ(t.type("\x1b"), "#D6" + std::string(kPrompt));
    EXPECT_EQ(t.type("A12\x1b"), "A12#D2" + std::string(kPrompt));
}

TEST(Pmc960Transcript, UntilWaitsForTheInputPattern) { // U6:7, L997
    TestDrive t;
    EXPECT_EQ(t.type("U6:7\r"), "U6:7");
    t.drive.setInput(2, true); // IN01'
    EXPECT_EQ(t.wait(2ms), "");
    t.drive.setInput(3, true); // IN02'
    EXPECT_EQ(t.wait(2ms), kPrompt);
}

TEST(Pmc960Transcript, DisplayFormatsFollowThc) { // THC bits 7-6 and 0 (L1828-1862)
    TestDrive t;
    t.writeEnable();
    EXPECT_EQ(t.type("THC40\r"), prompted("THC40"));
    EXPECT_EQ(t.type("V?"), prompted("V?0190"));   // 400 in hex, 16 bits
    EXPECT_EQ(t.type("A3E8\r"), prompted("A3E8")); // hex input
    EXPECT_EQ(t.type("A?"), prompted("A?03E8"));
    EXPECT_EQ(t.type("THC1\r"), "THC1}"); // no echo: the prompt is only }
    EXPECT_EQ(t.type("V?"), "400}");
    EXPECT_EQ(t.type("THC0\r"), prompted(""));
}

TEST(Pmc960Transcript, PercentStreamsUntilAnyCharacter) { // G%<cr>, L1189
    TestDrive t;
    EXPECT_EQ(t.type("G%\r"), "G%\r\n0");
    EXPECT_EQ(t.wait(250ms), "\r\n0\r\n0");
    EXPECT_EQ(t.type("x"), kPrompt);
    EXPECT_EQ(t.type("I%200\r"), "I%200\r\n0");
    EXPECT_EQ(t.wait(200ms), "\r\n0");
    EXPECT_EQ(t.type(" "), kPrompt);
}

TEST(Pmc960Transcript, FollowingErrorTripIsE1AndIdle) { // SF, L1505-1517, L2382
    TestDrive t;
    t.enable();
    EXPECT_EQ(t.type("SF8\r"), prompted("SF8"));
    EXPECT_EQ(t.type("J+\r"), prompted("J+"));
    EXPECT_EQ(t.wait(50ms), "#E1" + std::string(kPrompt));
    EXPECT_EQ(t.type("SM?"), prompted("SM?0"));
    EXPECT_EQ(t.type("SE?"), prompted("SE?E1"));
    EXPECT_EQ(t.type("SM&"), prompted("SM&2")); // the mode when the error happened
    EXPECT_EQ(t.type("SE&"), prompted("SE&E1"));
    const std::string bits = t.type("SS&"); // DRVON MOTION FORWARD (TOP VELOCITY as the lag builds up)
    EXPECT_TRUE(bits == prompted("SS&8A") || bits == prompted("SS&8E")) << bits;
    const std::string speed = t.type("V&"); // the motor's speed then: short of the 10 kHz jog
    const long atError = std::strtol(speed.c_str() + 2, nullptr, 10);
    EXPECT_GT(atError, 0);
    EXPECT_LT(atError, 100);
}

TEST(Pmc960Transcript, AsyncErrorsWaitForThePromptInHostMode) { // L2290-2292
    TestDrive t;
    t.writeEnable();
    t.enable();
    EXPECT_EQ(t.type("THC80\r"), prompted("THC80"));
    t.type("SF8\r");
    EXPECT_EQ(t.type("J+\r"), prompted("J+"));
    EXPECT_EQ(t.wait(50ms), ""); // held
    EXPECT_EQ(t.type("SW1\r"), "SW1#E1" + std::string(kPrompt));
}

TEST(Pmc960Transcript, EstopDuringMotionIsE0) { // L2381
    TestDrive t;
    t.enable();
    t.type("J+\r");
    t.wait(10ms);
    t.drive.setLine(drive_core::pmc960::Pmc960Line::Estop, true);
    EXPECT_EQ(t.drive.takeTransmitted(), "#E0" + std::string(kPrompt));
    t.wait(100ms);
    EXPECT_EQ(t.type("SM?"), prompted("SM?0"));
    EXPECT_EQ(t.type("J+"), prompted("J+#B3"));
}

} // namespace
} // namespace pmc960_test

namespace pmc960_test {
namespace {

TEST(Pmc960Transcript, SoftwareLimitsStopMotion) { // THS1 + SL (L1555-1575)
    TestDrive t;
    t.writeEnable();
    t.enable();
    t.type("SLF10000\r");
    t.type("SLR5000-\r");
    EXPECT_EQ(t.type("THS1\r"), prompted("THS1"));
    EXPECT_EQ(t.type("G20000+"), prompted("G20000+#B8"));
    EXPECT_EQ(t.type("I6000-"), prompted("I6000-#B9"));
    EXPECT_EQ(t.type("J+\r"), prompted("J+"));
    t.wait(2000ms);
    EXPECT_FALSE(t.drive.state().motion.moving());
    const double position = t.drive.state().motion.commanded_counts();
    EXPECT_GE(position, 10000);
    EXPECT_LT(position, 10100);                // stopped at the TUB rate just past the limit
    EXPECT_EQ(t.type("J+\r"), prompted("J+")); // into the limit: no motion, no message
    t.wait(10ms);
    EXPECT_FALSE(t.drive.state().motion.moving());
}

} // namespace
} // namespace pmc960_test

namespace pmc960_test {
namespace {

// Stop forms that are whole commands (acceptance finding #A2: the next command was read into the G line).
// `start` (with its <cr>) sets the axis moving; `stop` acts and prompts at once, without a <cr>, and what is
// typed next is a command of its own.
void expectStopEndsAtOnce(const char* start, const char* stop) {
    TestDrive t;
    t.enable();
    t.type(std::string(start) + "\r");
    t.wait(20ms);
    ASSERT_TRUE(t.drive.state().motion.moving()) << start;
    EXPECT_EQ(t.type(stop), prompted(stop));
    t.wait(100ms);
    EXPECT_FALSE(t.drive.state().motion.moving()) << stop;
    EXPECT_EQ(t.type("A?"), prompted("A?4000"));
}

TEST(Pmc960Transcript, GoStarStopsAndPromptsWithoutCr) { // G <display>, * stop system motion: L1169, L1181
    expectStopEndsAtOnce("G100000+", "G*");
}

TEST(Pmc960Transcript, HomeStarStopsAndPromptsWithoutCr) { // H* beside H15+<cr> and H,-<cr>: L1214-1216
    expectStopEndsAtOnce("H4000+", "H*"); // at the TUH home speed: seconds to go
}

TEST(Pmc960Transcript, EncoderHomeEndsAtItsDirection) { // H [<sync>] <direction>, no <cr>: L733, L1222, L1246
    TestDrive t;
    t.writeEnable();
    t.type("THA0\r");
    t.enable();
    EXPECT_EQ(t.type("H+"), prompted("H+"));
    EXPECT_TRUE(t.drive.state().motion.moving());
    EXPECT_EQ(t.type("A?"), prompted("A?4000"));
    EXPECT_EQ(t.type("H*"), prompted("H*")); // L1250
    t.wait(100ms);
    EXPECT_FALSE(t.drive.state().motion.moving());
}

TEST(Pmc960Transcript, CamStarStopsAndPromptsWithoutCr) { // c* among the stop commands (L1684), like C^ (L1101)
    expectStopEndsAtOnce("C1000:100", "C*");
}

TEST(Pmc960Transcript, IndexAndJogStarStayInTheirLine) { // #<direction># then <cr>: L1255, L1266, J,-*+*- L1296
    TestDrive t;
    t.enable();
    t.type("I100000+\r");
    t.wait(20ms);
    EXPECT_EQ(t.type("I*"), "I*"); // a direction: the line stays open for more and its <cr>
    EXPECT_EQ(t.type("\r"), kPrompt);
}

} // namespace
} // namespace pmc960_test
