// A simulated BDS5 driven the way a terminal drives it, for transcript tests: type bytes, let simulated
// time pass, read what the drive sent back.
#pragma once

#include "drive_core/bds5/bds5_drive.h"

#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <vector>

namespace bds5_test {

using namespace std::chrono_literals;

class TestDrive {
public:
    TestDrive() {
        drive.powerUp();
        type("");
    }
    // Sends bytes, runs `run` of simulated time in 1 ms ticks and then until the UART has sent
    // everything (9600 baud: about a character a millisecond), returns what the drive sent.
    std::string type(std::string_view bytes, std::chrono::milliseconds run = 1ms) {
        drive.receive(bytes);
        for (auto t = 0ms; t < run; t += 1ms) drive.step(1ms);
        for (int i = 0; i < 10000 && drive.transmitting(); ++i) drive.step(1ms);
        return drive.takeTransmitted();
    }
    std::string wait(std::chrono::milliseconds run) { return type("", run); }
    // >BDS, one line per l-> prompt, Esc (L9953-9968), as Motion Link downloads a program.
    void download(const std::vector<std::string>& lines) {
        ASSERT_EQ(type(">BDS\r"), ">BDS\r\nl->");
        for (const std::string& l : lines) ASSERT_EQ(type(l + "\r"), l + "\r\nl->");
        ASSERT_EQ(type("\x1b"), "\r\n-->");
    }

    drive_core::bds5::Bds5Drive drive;
};

// How often `needle` occurs in `text`.
inline int count(const std::string& text, const std::string& needle) {
    int n = 0;
    for (auto at = text.find(needle); at != std::string::npos; at = text.find(needle, at + needle.size())) ++n;
    return n;
}

} // namespace bds5_test
