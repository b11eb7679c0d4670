// A simulated PMC-960 driven the way a terminal or host drives it, for transcript tests: send bytes, let
// simulated time pass, read what the controller sent back. The line is unlimited (no baud pacing).
#pragma once

#include "drive_core/pmc960/pmc960_drive.h"

#include <gtest/gtest.h>

#include <chrono>
#include <string>

namespace pmc960_test {

using namespace std::chrono_literals;
inline constexpr std::string_view kPrompt = "\r\n=}";

class TestDrive {
public:
    TestDrive() {
        drive.setLineRateLimited(false);
        drive.powerUp();
        drive.takeTransmitted();
    }
    // Sends bytes, handles them at once, lets `run` of simulated time pass in 1 ms ticks.
    std::string type(std::string_view bytes, std::chrono::milliseconds run = 0ms) {
        drive.receive(bytes);
        drive.step(0ms);
        for (auto t = 0ms; t < run; t += 1ms) drive.step(1ms);
        return drive.takeTransmitted();
    }
    std::string wait(std::chrono::milliseconds run) { return type("", run); }
    // SW1, so P and T commands may write.
    void writeEnable() { ASSERT_EQ(type("SW1\r"), std::string("SW1") + std::string(kPrompt)); }
    // SM2: position mode, the drive enabled, so motion may be commanded.
    void enable() { ASSERT_EQ(type("SM2\r"), std::string("SM2") + std::string(kPrompt)); }
    // Writes a program the way a host downloads it: P{ } erases the buffer, P<cr> appends, ESC leaves.
    void load(std::string_view text) {
        writeEnable();
        ASSERT_EQ(type("P{}"), std::string("P{}") + std::string(kPrompt));
        type("P\r");
        type(text);
        ASSERT_EQ(type("\x1b"), kPrompt);
    }

    drive_core::pmc960::Pmc960Drive drive;
};

inline std::string prompted(std::string_view text) {
    return std::string(text) + std::string(kPrompt);
}

} // namespace pmc960_test
