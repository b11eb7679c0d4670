// Transcript tests: the bytes a user types into the simulated BDS5, and the exact bytes it sends back,
// as the manual's serial-communication transcripts show them (seed-bds5 §2.3-2.4).
#include "drive_core/bds5/bds5_drive.h"

#include <gtest/gtest.h>

using drive_core::bds5::Bds5Drive;
using namespace std::chrono_literals;

namespace {

class Bds5Transcript : public ::testing::Test {
protected:
    void SetUp() override {
        drive.powerUp();
        signOn = drain();
    }
    // Lets the UART send everything (9600 baud: about a character a millisecond).
    std::string drain() {
        drive.step(1ms);
        for (int i = 0; i < 10000 && drive.transmitting(); ++i) drive.step(1ms);
        return drive.takeTransmitted();
    }
    // Sends bytes as a terminal would and returns what the drive sent back.
    std::string type(std::string_view bytes) {
        drive.receive(bytes);
        return drain();
    }
    Bds5Drive drive;
    std::string signOn;
};

} // namespace

TEST_F(Bds5Transcript, PowerUpSendsSignOnThenPrompt) {
    EXPECT_EQ(signOn, "\r\n" + std::string(drive_core::bds5::kSignOn) + "\r\n-->");
    EXPECT_TRUE(drive.promptPending());
}

TEST_F(Bds5Transcript, EmptyLineAnswersCrLfPrompt) {
    EXPECT_EQ(type("\r"), "\r\n-->");
}

TEST_F(Bds5Transcript, EscapeInInteractiveModeAnswersLikeCr) {
    EXPECT_EQ(type("\x1b"), "\r\n-->");
}

TEST_F(Bds5Transcript, EveryCharacterIsEchoedAsItArrives) {
    EXPECT_EQ(type("P"), "P");
    EXPECT_EQ(type(" \"HI"), " \"HI");
    EXPECT_EQ(type("\"\r"), "\"\r\nHI\r\n-->");
}

TEST_F(Bds5Transcript, PrintQuotedText) {
    EXPECT_EQ(type("P \"HELLO, WORLD\"\r"), "P \"HELLO, WORLD\"\r\nHELLO, WORLD\r\n-->");
}

TEST_F(Bds5Transcript, AssignmentGivesOnlyThePrompt) {
    EXPECT_EQ(type("X1=1000\r"), "X1=1000\r\n-->");
    EXPECT_EQ(type("X2 1000\r"), "X2 1000\r\n-->");
}

TEST_F(Bds5Transcript, PrintVariableRightJustifiedInTwelveColumns) {
    type("X1=1000\r");
    EXPECT_EQ(type("P X1\r"), "P X1\r\n        1000\r\n-->");
}

TEST_F(Bds5Transcript, PrintSegZeroHasElevenSpaces) {
    // L9650: P of a zero value is 11 spaces and "0"; X7 stands in for SEG until motion exists.
    EXPECT_EQ(type("P X7\r"), "P X7\r\n           0\r\n-->");
}

TEST_F(Bds5Transcript, PrintWidthOverflowFillsWithX) {
    type("X1=1024\r");
    EXPECT_EQ(type("P X1[3]\r"), "P X1[3]\r\nXXX\r\n-->");
    EXPECT_EQ(type("P X1[5]\r"), "P X1[5]\r\n 1024\r\n-->");
}

TEST_F(Bds5Transcript, PrintHexIsNineWide) {
    type("X1=65280\r");
    EXPECT_EQ(type("P X1[H]\r"), "P X1[H]\r\n    FF00H\r\n-->");
}

TEST_F(Bds5Transcript, ExpressionsFollowTheManualsExamples) {
    EXPECT_EQ(type("P 1+2*3\r"), "P 1+2*3\r\n           7\r\n-->");
    EXPECT_EQ(type("P 280/100*53\r"), "P 280/100*53\r\n         159\r\n-->");
}

TEST_F(Bds5Transcript, UnknownCommandGivesErr80WithMessageAtColumn40) {
    const std::string entry = "ERR 80 'FOO'";
    const std::string expected =
        "FOO\r\n\r\n\n\a" + entry + std::string(40 - entry.size(), ' ') + "INVALID INSTRUCTION\r\n-->";
    EXPECT_EQ(type("FOO\r"), expected);
}

TEST_F(Bds5Transcript, ZeroDivideNamesTheExpression) {
    const std::string out = type("P 1/0\r");
    EXPECT_NE(out.find("\aERR 92 '1/0'"), std::string::npos) << out;
    EXPECT_NE(out.find("ZERO DIVIDE\r\n-->"), std::string::npos) << out;
}

TEST_F(Bds5Transcript, EmbeddedQuoteIsErr87) {
    const std::string out = type("P\"BAD\"\r");
    EXPECT_NE(out.find("\aERR 87"), std::string::npos) << out;
}

TEST_F(Bds5Transcript, AsynchronousErrorIsHeldUntilCr) {
    drive.raiseFault(17);
    EXPECT_EQ(drain(), "") << "nothing may be sent while a prompt is pending";
    EXPECT_EQ(type("\r"), "\r\n\aERR 17 FEEDBACK LOSS\r\n-->");
}

TEST_F(Bds5Transcript, CommandTypedWhileErrorWaitsIsIgnored) {
    drive.raiseFault(17);
    EXPECT_EQ(type("X1=5\r"), "X1=5\r\nERROR MSG WAITING--COMMAND IGNORED\r\n\r\n\n\aERR 17 FEEDBACK LOSS\r\n-->");
    EXPECT_EQ(type("P X1\r"), "P X1\r\n           0\r\n-->") << "the ignored assignment must not happen";
}

TEST_F(Bds5Transcript, BackspaceErasesTheLastCharacter) {
    EXPECT_EQ(type("P 12\b3\r"), "P 12\b \b3\r\n          13\r\n-->");
}

TEST_F(Bds5Transcript, ErrorHistoryListsNewestFirst) {
    type("FOO\r");
    const std::string out = type("ERR HIST\r");
    EXPECT_EQ(out, "ERR HIST\r\nERR 80 INVALID INSTRUCTION\r\nERR 199 DRIVE POWERED UP\r\n-->");
}

TEST_F(Bds5Transcript, UserVariablesSurvivePowerCycle) {
    type("X5=42\r");
    drive.powerUp();
    drain();
    EXPECT_EQ(type("P X5\r"), "P X5\r\n          42\r\n-->");
}
