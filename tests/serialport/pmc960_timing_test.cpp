// Pmc960Timing: the PMC-960's time-outs follow the baud rate and the command's time (issue 11), so a slow
// line is not taken for a dead controller and a fast one notices a lost answer quickly.
#include "serialport/pmc960_timing.h"

#include <gtest/gtest.h>

using serialport::Pmc960Timing;

TEST(Pmc960Timing, WireTimeIsTenBitsACharacterAtTheBaudRate) {
    EXPECT_EQ(Pmc960Timing::wireMs(96, 9600), 100);
    EXPECT_EQ(Pmc960Timing::wireMs(3, 300), 100);
    EXPECT_EQ(Pmc960Timing::wireMs(1, 38400), 1); // rounded up
    EXPECT_EQ(Pmc960Timing::wireMs(500, 0), 0);   // no wire (the simulator without pacing)
}

TEST(Pmc960Timing, ACommandsTimeOutIsItsWireTimePlusTheCommandTime) {
    // "A3500\r": 6 out, 6 echoed, up to 64 answered, 4 of prompt = 80 characters.
    EXPECT_EQ(Pmc960Timing::commandTimeoutMs("A3500\r", 9600), Pmc960Timing::kCommandMs + 84); // 83.3 up
    EXPECT_EQ(Pmc960Timing::commandTimeoutMs("A3500\r", 300), Pmc960Timing::kCommandMs + 2667);
    EXPECT_EQ(Pmc960Timing::commandTimeoutMs("A3500\r", 0), Pmc960Timing::kCommandMs);
    // Slower lines wait longer, never less.
    int previous = 0;
    for (const int baud : {38400, 19200, 9600, 4800, 2400, 1200, 600, 300}) {
        const int ms = Pmc960Timing::commandTimeoutMs("SW1\r", baud);
        EXPECT_GT(ms, previous) << baud;
        previous = ms;
    }
}

TEST(Pmc960Timing, DwellsAndMotionWaitsAddTheirOwnTime) {
    EXPECT_EQ(Pmc960Timing::commandMs("A?"), Pmc960Timing::kCommandMs);
    EXPECT_EQ(Pmc960Timing::commandMs("D300\r"), Pmc960Timing::kCommandMs + 308);
    EXPECT_EQ(Pmc960Timing::commandMs("D65535\r"), Pmc960Timing::kCommandMs + 65543);
    EXPECT_EQ(Pmc960Timing::commandMs("I+,"), Pmc960Timing::kCommandMs + Pmc960Timing::kMotionWaitMs);
    EXPECT_EQ(Pmc960Timing::commandMs("J100+;"), Pmc960Timing::kCommandMs + Pmc960Timing::kMotionWaitMs);
}

TEST(Pmc960Timing, PollsAndEditorLines) {
    EXPECT_EQ(Pmc960Timing::pollTimeoutMs(9600), Pmc960Timing::kCommandMs + 20); // 19 characters
    EXPECT_EQ(Pmc960Timing::pollTimeoutMs(300), Pmc960Timing::kCommandMs + 634);
    // "A100\r" and its echo "A100\r\n" (+4): 15 characters.
    EXPECT_EQ(Pmc960Timing::expectTimeoutMs("A100\r", "A100\r\n", 1200), Pmc960Timing::kCommandMs + 125);
}
