// The BDS5's serial behaviour beyond the line discipline: baud timing, autobaud, multidrop, watchdog,
// and the v3 switches (ECHO, MSG, MONITOR), PROMPT and DEP (seed-bds5 §2.1-2.8, §2.11).
#include "bds5_test_drive.h"

using namespace bds5_test;
using drive_core::bds5::Bds5DriveMode;

namespace {
void powerCycle(TestDrive& t) {
    t.drive.powerUp();
    t.wait(5ms);
}
} // namespace

TEST(Bds5Serial, CharactersLeaveAtTheBaudRate) { // 9600 baud 8N1: 960 characters a second
    TestDrive t;
    t.drive.receive("P \"0123456789012345678901234567890123456789\"\r");
    t.drive.step(std::chrono::milliseconds(1));
    std::size_t sent = t.drive.takeTransmitted().size();
    for (int i = 0; i < 49; ++i) {
        t.drive.step(std::chrono::milliseconds(1));
        sent += t.drive.takeTransmitted().size();
    }
    EXPECT_NEAR(double(sent), 48.0, 2.0) << "50 ms carry 48 characters";
    EXPECT_TRUE(t.drive.transmitting());
}

TEST(Bds5Serial, BaudIsTakenAtPowerUp) {
    TestDrive t;
    t.type("BAUD 19200\r");
    EXPECT_EQ(t.drive.baudRate(), 9600);
    powerCycle(t);
    EXPECT_EQ(t.drive.baudRate(), 19200);
}

TEST(Bds5Serial, AutobaudWaitsForACarriageReturn) { // L5292-5318
    TestDrive t;
    t.type("ABAUD=1\r");
    t.drive.powerUp();
    EXPECT_EQ(t.wait(100ms), "") << "silent until the host sends CR";
    EXPECT_EQ(t.type("X"), "");
    const std::string out = t.type("\r");
    EXPECT_EQ(out, "\r\n" + std::string(drive_core::bds5::kSignOn) + "\r\n-->");
}

TEST(Bds5Serial, MotionOffAtPowerUpForcesAutobaudAndSingleDrop) {
    TestDrive t;
    t.type("ADDR=65\r");
    t.drive.setDedicatedInput("MOTION", false);
    t.drive.powerUp();
    EXPECT_EQ(t.wait(50ms), "");
    EXPECT_TRUE(t.type("\r").ends_with("\r\n-->"));
    EXPECT_EQ(t.type("P ADDR\r"), "P ADDR\r\n           0\r\n-->");
}

TEST(Bds5Serial, MultidropAxisSleepsUntilCalled) { // L5430-5449, L10015-10028
    TestDrive t;
    EXPECT_EQ(t.type("ADDR=65\r"), "ADDR=65\r\n") << "multidrop at once, asleep until \\A (L5449-5451)";
    EXPECT_EQ(t.type("\\A"), "\r\nA->") << "the ID prefixes the prompt";
    powerCycle(t);
    EXPECT_EQ(t.type("P 1\r", 20ms), "") << "asleep: it executes but transmits nothing";
    EXPECT_EQ(t.type("\\B"), "") << "another axis is called";
    EXPECT_EQ(t.type("\\A"), "\r\nA->");
    EXPECT_EQ(t.type("P 7\r"), "P 7\r\n           7\r\nA->");
    EXPECT_EQ(t.type("\\\r"), "") << "'\\' alone puts every axis to sleep";
    EXPECT_EQ(t.type("X1=5\r"), "");
    EXPECT_EQ(t.type("\\*X2=6\r"), "") << "broadcast (L10017-10019): executes, does not answer";
    t.type("\\A");
    EXPECT_EQ(t.type("P X2\r"), "P X2\r\n           6\r\nA->");
    EXPECT_EQ(t.type("P 6*7\r"), "P 6*7\r\n          42\r\nA->") << "a '*' not after '\\' is no broadcast";
}

// "A backslash puts ALL drives on the serial line to sleep" (L5449): a second backslash right after it is not
// an axis ID but a new attention: two backslashes and a star are sleep-all, then broadcast, as a host that
// clears the line first sends them.
TEST(Bds5Serial, ABackslashAfterABackslashStartsANewAttention) {
    TestDrive t;
    t.type("ADDR=65\r");
    EXPECT_EQ(t.type("\\\\*X2=6\r"), "") << "broadcast: executes, does not answer";
    EXPECT_EQ(t.type("\\\\A"), "\r\nA->");
    EXPECT_EQ(t.type("P X2\r"), "P X2\r\n           6\r\nA->");
}

// "Setting ADDR to 65 makes this axis address "A" and automatically puts the BDS5 in Multidrop mode. This
// axis then waits for the "\A."" (L5449-5451): the echo of the line, then nothing, not even a prompt,
// until the host calls the new ID; what is typed meanwhile reaches an axis that does not listen.
TEST(Bds5Serial, NewAddressSleepsUntilItsWakeUp) {
    TestDrive t;
    EXPECT_EQ(t.type("ADDR=66\r"), "ADDR=66\r\n") << "no B-> before \\B";
    EXPECT_EQ(t.wait(50ms), "");
    EXPECT_EQ(t.type("X1=5\r", 20ms), "") << "asleep: no echo, no prompt";
    EXPECT_EQ(t.type("\\A"), "") << "another axis is called";
    EXPECT_EQ(t.type("\\B"), "\r\nB->");
    EXPECT_EQ(t.type("P X1 ADDR\r"), "P X1 ADDR\r\n           0          66\r\nB->")
        << "the line typed asleep was not for this axis";
    EXPECT_EQ(t.type("ADDR=67\r"), "ADDR=67\r\n") << "a new ID sleeps again";
    EXPECT_EQ(t.type("\\C"), "\r\nC->");
    EXPECT_EQ(t.type("ADDR=0\r"), "ADDR=0\r\n-->") << "single-drop answers at once";
}

TEST(Bds5Serial, MultidropPromptsOfEveryMode) {
    TestDrive t;
    t.type("ADDR=66\r");
    t.type("\\B"); // the new ID waits for its wake-up (L5449-5451)
    EXPECT_EQ(t.type(">BDS\r"), ">BDS\r\nBl>");
    t.type("1$\r");
    t.type("D 100000\r");
    EXPECT_EQ(t.type("\x1b"), "\r\nB->");
    t.type("RUN 1\r", 5ms);
    EXPECT_TRUE(t.type("\x1b").ends_with("\r\nB=>"));
    t.type("B\r");
    EXPECT_EQ(t.type("ED\r"), "ED\r\nBe>");
}

TEST(Bds5Serial, WatchdogBreaksAndDisablesWithoutCr) { // L5328-5342
    TestDrive t;
    t.download({"1$", "D 100000"});
    t.type("EN\r");
    t.type("WTIME=200\r");
    t.type("WATCH ON\r");
    EXPECT_EQ(t.type("RUN 1\r", 150ms), "RUN 1\r\n");
    const std::string out = t.wait(100ms);
    EXPECT_EQ(out, "\r\n\n\aERR 105 SERIAL WDOG\r\n-->") << out;
    EXPECT_EQ(t.type("PS\r"), "PS\r\nFAULT\r\n-->");
}

TEST(Bds5Serial, EchoOffSendsOnlyTheLineEnd) { // v3 ECHO (L9303)
    TestDrive t;
    t.type("ECHO 0\r");
    EXPECT_EQ(t.type("P 5\r"), "           5\r\n-->");
}

TEST(Bds5Serial, PromptOffSuppressesPrompts) { // L5320-5326
    TestDrive t;
    EXPECT_EQ(t.type("PROMPT OFF\r"), "PROMPT OFF\r\n");
    EXPECT_EQ(t.type("P 5\r"), "P 5\r\n           5\r\n");
}

TEST(Bds5Serial, MsgOffSuppressesSignOnAndMonitorMessage) { // v3 MSG (L9304)
    TestDrive t;
    t.type("MSG 0\r");
    t.drive.powerUp();
    EXPECT_EQ(t.wait(5ms), "-->");
}

TEST(Bds5Serial, MonitorOnEntersMonitorModeAtRun) { // v3 MONITOR (L9302)
    TestDrive t;
    t.download({"1$", "D 100000"});
    t.type("MONITOR 1\r");
    EXPECT_EQ(t.type("RUN 1\r", 5ms), "RUN 1\r\n\r\n\nENTER MONITOR MODE. PUSH ESCAPE TO EXIT\r\n==>");
}

TEST(Bds5Serial, DepCutsErrorsTo40Characters) { // L6102-6108
    TestDrive t;
    t.type("DEP ON\r");
    EXPECT_EQ(t.type("FOO\r"), "FOO\r\n\r\n\n\aERR 80 'FOO'                            \r\n-->");
}
