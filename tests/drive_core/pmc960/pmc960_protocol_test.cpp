// The PMC-960 host protocol: status polls via the 1DH attention byte, the 16-bit communications checksum
// (5.3.6, digest §4.8), binary numbers, <attn><ID> talker selection, autobaud, persistence across power.
#include "pmc960_test_drive.h"

#include <numeric>

namespace pmc960_test {
namespace {

constexpr char kAttn = 0x1D;

std::string attn(char letter) {
    return std::string(1, kAttn) + letter;
}

TEST(Pmc960Protocol, PollsAnswerAtOnceWithoutPrompt) {
    TestDrive t;
    EXPECT_EQ(t.type(attn('g')), "0\r");
    EXPECT_EQ(t.type(attn('v')), "0\r");
    EXPECT_EQ(t.type(attn('m')), "02\r"); // SS: direction bit forward, drive off
    EXPECT_EQ(t.type(attn('s')), "0000\r");
    EXPECT_EQ(t.type(attn('b')), "  0\r");
}

TEST(Pmc960Protocol, PollsWorkInTheMiddleOfACommandAndDuringMotion) {
    TestDrive t;
    t.enable();
    t.type("J+\r");
    t.wait(100ms); // the motor at the jog's speed
    EXPECT_EQ(t.type("A3" + attn('v') + "5\r"), "A3100\r5" + std::string(kPrompt));
    EXPECT_EQ(t.type("A?"), prompted("A?35"));
    EXPECT_EQ(t.type(attn('m')), "8E\r"); // DRVON MOTION TOP-VELOCITY FORWARD
}

TEST(Pmc960Protocol, ChecksumSumsReceivedBytesAndResets) {
    TestDrive t;
    EXPECT_EQ(t.type(attn('h')), "0\r");
    const std::string sent = "A3500\rV?";
    t.type(sent);
    t.type(attn('g')); // polls are not counted
    const int sum = std::accumulate(sent.begin(), sent.end(), 0, [](int s, char c) { return s + (unsigned char)c; });
    EXPECT_EQ(t.type(attn('h')), std::to_string(sum) + "\r");
    EXPECT_EQ(t.type(attn('h')), "0\r"); // read-and-reset
}

TEST(Pmc960Protocol, ChecksumWrapsAtSixteenBits) {
    TestDrive t;
    t.type(attn('h'));
    const std::string block(700, 'z'); // 700 x 7AH = 85400 -> 85400 - 65536
    t.type("P?");
    t.type("\x1b");
    t.drive.receive(block);
    t.drive.step(0ms);
    t.drive.takeTransmitted();
    const int expected = (700 * 0x7A + 'P' + '?' + 0x1B) % 65536;
    EXPECT_EQ(t.type(attn('h')), std::to_string(expected) + "\r");
}

TEST(Pmc960Protocol, BinaryInputVelocity) { // example 21, L1886-1888: v 00 03 78 = 888
    TestDrive t;
    t.writeEnable();
    EXPECT_EQ(t.type("THCC0\r"), prompted("THCC0"));
    EXPECT_EQ(t.type(std::string("v\0\x03\x78", 4)), prompted("v"));
    EXPECT_EQ(t.type("V?"), prompted(std::string("V?\x03\x78", 4)));
}

TEST(Pmc960Protocol, BinaryInputIndexWithDoubledAttention) { // example 22, L1894-1903: 7 bytes, no <cr>
    TestDrive t;
    t.writeEnable();
    t.type("THCC0\r");
    EXPECT_EQ(t.type(std::string("i\0\0\0\x1d\x1d\x4c", 7)), prompted("i")); // no terminator (L1877)
    EXPECT_EQ(t.drive.state().reg.distance, 7500);
    EXPECT_EQ(t.type("I?"), prompted(std::string("I?\0\0\x1d\x4c", 6)));
}

// No terminator is accepted after a binary number (L1877): its last byte ends the command, and what is
// typed next is a command of its own (acceptance finding: binary I stayed open until <cr>).
TEST(Pmc960Protocol, BinaryNumberEndsTheCommandWithoutTerminator) {
    TestDrive t;
    t.writeEnable();
    t.type("THCC0\r");
    EXPECT_EQ(t.type(std::string("i\0\0\0\x1d\x1d\x4c", 7) + std::string("v\0\x03\x78", 4)),
              prompted("i") + prompted("v")); // L1894, then L1886
    EXPECT_EQ(t.drive.state().reg.distance, 7500);
    EXPECT_EQ(t.drive.state().reg.velocity, 888);
    EXPECT_EQ(t.type(std::string("j\0\0\x32", 4)), prompted("j")); // J<speed><cr> (L1266): 16 bits
    EXPECT_EQ(t.drive.state().reg.jogSpeed, 50);
    EXPECT_EQ(t.type(std::string("h\0\0\x0f", 4)), prompted("h")); // H<location><cr> (L1197)
    EXPECT_EQ(t.drive.state().reg.homeLocation, 15);
    EXPECT_EQ(t.type(std::string("tgp\0\x11", 5)), prompted("tgp")); // TGP17<cr> (L1769): an 8-bit gain
    EXPECT_EQ(t.drive.state().table.inUse("TGP"), 17);
    EXPECT_EQ(t.drive.state().reg.lastError, 0);
}

TEST(Pmc960Protocol, BinaryInputHexValuesAreBinaryToo) { // all numbers binary but THC TUA TUP TUS (L1870)
    TestDrive t;
    t.writeEnable();
    t.type("THCC0\r");
    EXPECT_EQ(t.type(std::string("sp\0\x30", 4)), prompted("sp")); // SP: hex in ASCII input (L1616)
    EXPECT_EQ(t.drive.state().reg.profile, 0x30);
    EXPECT_EQ(t.type(std::string("ths\0\x01", 5)), prompted("ths"));
    EXPECT_EQ(t.drive.state().table.inUse("THS"), 1);
    EXPECT_EQ(t.type("THC00\r"), prompted("THC00")); // THC stays ASCII hex
    EXPECT_EQ(t.drive.state().reg.lastError, 0);
}

TEST(Pmc960Protocol, BinaryCamPositionEndsTheSegment) { // C<position><cr> (L1099, L1117), no terminator (L1877)
    TestDrive t;
    t.writeEnable();
    t.enable();
    EXPECT_EQ(t.type("C1000:100\r"), prompted("C1000:100"));
    t.type("THCC0\r");
    EXPECT_EQ(t.type(std::string("c\0\0\0\x07\xd0", 6)), prompted("c")); // C2000 at the running speed
    EXPECT_EQ(t.drive.state().reg.lastError, 0);
    EXPECT_TRUE(t.drive.state().motion.camRunning());
}

TEST(Pmc960Protocol, BinaryGoStillTakesItsSign) { // G <position> [<sync>] <sign> <cr> (L1169)
    TestDrive t;
    t.writeEnable();
    t.enable();
    t.type("THCC0\r");
    EXPECT_EQ(t.type(std::string("g\0\0\0\x01\xf4-", 7)), "g-"); // the sign is the position's (L1174)
    EXPECT_EQ(t.type("\r"), kPrompt);
    EXPECT_EQ(t.drive.state().reg.goPosition, -500);
}

TEST(Pmc960Protocol, BinaryDataByteEscIsData) { // only 1DH must be sent twice to be data (L1879)
    TestDrive t;
    t.writeEnable();
    t.type("THCC0\r");
    EXPECT_EQ(t.type(std::string("i\0\0\0\0\x1b", 6)), prompted("i")); // a distance of 27, not ESC
    EXPECT_EQ(t.drive.state().reg.distance, 27);
    EXPECT_EQ(t.drive.state().reg.lastError, 0);
}

TEST(Pmc960Protocol, BinaryOutputDoublesHash) { // L1906-1910: a data byte 23H is sent twice
    TestDrive t;
    t.writeEnable();
    t.type("THC80\r"); // hex in, binary out
    t.type("A23\r");   // 35 = 23H
    EXPECT_EQ(t.type("A?"), prompted(std::string("A?\0##", 5)));
}

TEST(Pmc960Protocol, BinaryPollsHaveFixedWidths) {
    TestDrive t;
    t.writeEnable();
    t.type("THCC0\r");
    t.type(std::string("N\0\0\0\x01\x02+", 7));                   // N to +258
    EXPECT_EQ(t.type(attn('g')), std::string("\0\0\x01\x02", 4)); // 32-bit position, no terminator
    EXPECT_EQ(t.type(attn('v')), std::string("\0\0", 2));         // 16-bit velocity
    EXPECT_EQ(t.type(attn('m')), std::string("\x02", 1));         // SS byte
}

TEST(Pmc960Protocol, AxisSelectionMakesListeners) { // L2543-2560
    TestDrive t;
    EXPECT_EQ(t.type(attn('Q')), "");
    EXPECT_FALSE(t.drive.talker());
    EXPECT_EQ(t.type("A5\r" + attn('v')), ""); // a listener acts only on <attn><ID>
    EXPECT_EQ(t.type(attn('=')), "");
    EXPECT_TRUE(t.drive.talker());
    EXPECT_EQ(t.type("A?"), prompted("A?4000"));
}

TEST(Pmc960Protocol, AxisIdIsThePromptCharacter) {
    TestDrive t;
    t.writeEnable();
    EXPECT_EQ(t.type("THIX\r"), "THIX\r\nX}");
    EXPECT_EQ(t.type("THI \r"), "THI #A5\r\nX}\r\nX}");
}

TEST(Pmc960Protocol, AutobaudWaitsForACarriageReturn) { // THB0, L1806-1826
    TestDrive t;
    t.writeEnable();
    t.type("THB0\r");
    t.drive.powerUp();
    EXPECT_EQ(t.drive.takeTransmitted(), "");
    EXPECT_EQ(t.type("xyz"), "");
    EXPECT_EQ(t.type("\r"), kPrompt);
    EXPECT_EQ(t.type("A?"), prompted("A?4000"));
}

TEST(Pmc960Protocol, TableSurvivesPowerCycleRegistersDoNot) {
    TestDrive t;
    t.writeEnable();
    t.type("TGP40\r");
    t.type("A1234\r");
    t.drive.powerUp();
    EXPECT_EQ(t.drive.takeTransmitted(), kPrompt);
    EXPECT_EQ(t.type("TGP?"), prompted("TGP?\r\nP-40"));
    EXPECT_EQ(t.type("A?"), prompted("A?4000"));
    EXPECT_EQ(t.type("SW?"), prompted("SW?0")); // write protected again
}

TEST(Pmc960Protocol, GenericPowerUpWithEstopChangesValuesInUse) { // L1717, L875
    TestDrive t;
    t.writeEnable();
    t.type("THC1\r"); // no echo stored in the table
    t.drive.setLine(drive_core::pmc960::Pmc960Line::Estop, true);
    t.drive.powerUp();
    t.drive.takeTransmitted();
    EXPECT_EQ(t.type("\r"), kPrompt); // generic: autobaud, decimal, echo
    EXPECT_EQ(t.type("THC?"), prompted("THC?\r\nC-01"));
    EXPECT_EQ(t.type("THC!"), prompted("THC!\r\nC-00"));
}

// Issue 19: a poll is answered "at any time during PMC operation" (5.3.3, L821), also while a routine run
// with B<label> executes (the controller polls its SCI for ESC and <attn> between commands, L2554-2564) and
// while it waits in a , or a dwell. The routine goes on: its output and its prompt come after, and the polls
// are not in the communications checksum.
TEST(Pmc960Protocol, PollsAreAnsweredWhileARoutineRuns) {
    using drive_core::pmc960::Pmc960Wait;
    TestDrive t;
    std::string busy = "@B\r";
    for (int i = 0; i < 100; ++i) busy += "A4000\r"; // 600 characters: 30 ms of execution without a wait
    t.load("@H\rSM2\rA4000\rV400\rI8192+,\rD300\rG!\r" + busy);
    t.type(attn('h'));
    std::string out = t.type("BH\r");
    // Simulated time passes until the routine is where the test wants it (5 s at most).
    auto runUntil = [&](auto reached) {
        for (int ms = 0; ms < 5000 && !reached(); ++ms) {
            t.drive.step(1ms);
            out += t.drive.takeTransmitted();
        }
        return reached();
    };
    const auto& interpreter = t.drive.interpreter();
    ASSERT_TRUE(runUntil([&] { return t.drive.state().motion.actual_counts() > 100; }));
    ASSERT_EQ(interpreter.wait(), Pmc960Wait::MotionDone); // in I8192+,
    const std::string moving = t.type(attn('g'));
    ASSERT_FALSE(moving.empty());
    EXPECT_EQ(moving.back(), '\r');
    const long position = std::stol(moving);
    EXPECT_GT(position, 100);
    EXPECT_LT(position, 8192);
    EXPECT_EQ(t.type(attn('b')), "H 3\r"); // SM2 A4000 V400 done

    ASSERT_TRUE(runUntil([&] { return interpreter.wait() == Pmc960Wait::Dwell; }));
    EXPECT_EQ(t.type(attn('b')), "H 4\r");

    ASSERT_TRUE(runUntil([&] { return t.drive.state().reg.lastLabel == 'B'; }));
    ASSERT_TRUE(interpreter.running());
    ASSERT_EQ(interpreter.wait(), Pmc960Wait::None); // executing, not waiting: answered between two commands
    const std::string executing = t.type(attn('b'));
    EXPECT_EQ(executing.substr(0, 2), "B ") << executing;
    EXPECT_EQ(executing.back(), '\r');

    ASSERT_TRUE(runUntil([&] { return !interpreter.running(); }));
    EXPECT_EQ(out.substr(0, 2), "BH");
    EXPECT_EQ(out.substr(out.size() - kPrompt.size()), kPrompt); // the routine ended as it would have
    EXPECT_EQ(out.find('#'), std::string::npos) << out;
    const std::string sent = "BH\r";
    const int sum = std::accumulate(sent.begin(), sent.end(), 0, [](int s, char c) { return s + (unsigned char)c; });
    EXPECT_EQ(t.type(attn('h')), std::to_string(sum) + "\r"); // the polls are not in it
}

// The same with the overrun model on: a routine that runs reads only ESC and <attn> from its one-character
// buffer, so a host honouring CTS gets the poll answered in the middle of it, with nothing lost.
TEST(Pmc960Overrun, PollsAreReadWhileARoutineRuns) {
    TestDrive t;
    std::string busy = "@H\r";
    for (int i = 0; i < 200; ++i) busy += "A4000\r";
    t.load(busy);
    t.drive.setOverrunModel(true);
    t.type("BH\r", 5ms);
    ASSERT_TRUE(t.drive.interpreter().running());
    std::string out;
    for (const char c : std::string("\x1d\x62")) { // <attn> b
        for (int wait = 0; wait < 100 && !t.drive.clearToSend(); ++wait) t.drive.step(std::chrono::microseconds(100));
        ASSERT_TRUE(t.drive.clearToSend()) << "the routine does not read its SCI"; // CTS held: the byte waits
        t.drive.receive(std::string_view(&c, 1));
        t.drive.step(2ms);
    }
    out = t.drive.takeTransmitted();
    EXPECT_TRUE(t.drive.interpreter().running());
    EXPECT_NE(out.find("H "), std::string::npos) << out;
    EXPECT_EQ(t.drive.overruns(), 0);
}

TEST(Pmc960Protocol, EpromProgramIsCopiedAtPowerUp) { // 5.10, L978-989
    TestDrive t;
    t.drive.setEprom("@PROGRAM\r@AI+\r\xFFgarbage");
    t.drive.powerUp();
    EXPECT_EQ(t.drive.state().program.text(), "@PROGRAM\r@AI+\r");
}

} // namespace
} // namespace pmc960_test

namespace pmc960_test {
namespace {

// The documented hazard (L2564-2568): i1000+ then <attn>v without flow control — the PMC is busy after
// the '+', 'v' overruns <attn> and is read as part of the index command: a syntax error.
TEST(Pmc960Overrun, PollAfterATriggerIsLostWithoutFlowControl) {
    drive_core::pmc960::Pmc960Drive drive;
    drive.setLineRateLimited(false);
    drive.setOverrunModel(true);
    drive.receive("SM2\r");
    for (int i = 0; i < 20; ++i) drive.step(1ms);
    drive.takeTransmitted();
    drive.receive("i1000+\x1dv");
    for (int i = 0; i < 30; ++i) drive.step(1ms);
    EXPECT_EQ(drive.takeTransmitted(), "i1000+v#A2\r\n=}");
    EXPECT_EQ(drive.overruns(), 1);
}

TEST(Pmc960Overrun, HostHonouringCtsLosesNothing) {
    drive_core::pmc960::Pmc960Drive drive;
    drive.setLineRateLimited(false);
    drive.setOverrunModel(true);
    std::string out;
    auto sendWithFlowControl = [&](std::string_view bytes) {
        for (const char c : bytes) {
            while (!drive.clearToSend()) drive.step(1ms);
            drive.receive(std::string_view(&c, 1));
            drive.step(2ms); // one character time at 9600 baud, and a little
        }
        for (int i = 0; i < 20; ++i) drive.step(1ms);
        out += drive.takeTransmitted();
    };
    drive.takeTransmitted();
    sendWithFlowControl("SM2\r");
    sendWithFlowControl("i1000+\x1dv");
    EXPECT_EQ(drive.overruns(), 0);
    EXPECT_EQ(out.find("#A2"), std::string::npos) << out;
    EXPECT_NE(out.find("i1000+"), std::string::npos);
}

} // namespace
} // namespace pmc960_test

namespace pmc960_test {
namespace {

TEST(Pmc960Bench, SideChannelDrivesTheMachineLines) { // servodesk-sim --control, the IDE's I/O panel
    TestDrive t;
    drive_core::SimulatorControls& bench = *t.drive.controls();
    EXPECT_EQ(drive_core::runSimulatorCommand(bench, "input 1 on"), "OK");
    EXPECT_EQ(t.type("SI?"), prompted("SI?0001"));
    t.enable();
    t.type("J+\r");
    t.wait(10ms);
    EXPECT_EQ(drive_core::runSimulatorCommand(bench, "motion off"), "OK"); // ESTOP'
    EXPECT_EQ(t.drive.takeTransmitted(), "#E0" + std::string(kPrompt));
    EXPECT_FALSE(bench.status().motionInput);
    EXPECT_TRUE(bench.status().inputs[0]);
}

} // namespace
} // namespace pmc960_test
