// libFuzzer target for the simulated PMC-960's serial input (issue 9): any byte stream at the port, with
// time passing, machine lines and power cycles in between, is answered or ignored — never a crash, a hang
// or unbounded state. The same file is the body of pmc960_fuzz_replay, which runs the seed corpus
// (tests/drive_core/pmc960/fuzz_corpus) in every CTest build.
#include "drive_core/pmc960/pmc960_drive.h"

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

// Operations are escaped by the bytes 0xF9-0xFF; every other byte is received as it is:
//   0xF9 n   step(n+1 ms)      0xFA n   setInput(n%16 + 1, n & 0x80)
//   0xFB n   machine line n%5 (ESTOP' FAULT' BREAK' DRVRDY' SENSOR) set to n & 0x80
//   0xFC     powerUp()         0xFD n   overrun model on/off (n & 1)
//   0xFE n   step(7n + 1 us)   0xFF x   receive the literal byte x
//
// An input costs what it asks for and no more (issue 20, item 12): every millisecond of drive time is a
// servo tick with the plant in it, so an input gets at most 500 ms of drive time in all (later steps do
// nothing), then the 60 ms of the ending. 500 ms holds every timed behaviour an input can reach from the
// port: the 300 ms a power-up takes before the prompt, a jog's ramp, a dwell of a few ticks, the
// following-error trip; 4 KB of steps used to ask for up to 9 minutes of drive time and ran ~400 a second.

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace std::chrono_literals;
    using drive_core::pmc960::Pmc960Line;
    drive_core::pmc960::Pmc960Drive drive;
    drive.setLineRateLimited(false);
    std::string pending;
    std::size_t sent = 0;
    auto timeLeft = std::chrono::microseconds(500ms);
    auto step = [&](std::chrono::microseconds dt) {
        dt = std::min(dt, timeLeft);
        if (dt <= 0us) return;
        timeLeft -= dt;
        drive.step(dt);
    };
    auto flush = [&] {
        drive.receive(pending);
        pending.clear();
        drive.step(0ms);
        sent += drive.takeTransmitted().size();
    };
    for (std::size_t i = 0; i < size; ++i) {
        const std::uint8_t b = data[i];
        if (b < 0xF9 || i + 1 >= size) {
            pending += char(b);
            continue;
        }
        const std::uint8_t n = b == 0xFC ? 0 : data[++i];
        flush();
        switch (b) {
        case 0xF9: step(std::chrono::milliseconds(n + 1)); break;
        case 0xFA: drive.setInput(n % 16 + 1, (n & 0x80) != 0); break;
        case 0xFB: {
            static constexpr Pmc960Line kLines[] = {Pmc960Line::Estop, Pmc960Line::Fault, Pmc960Line::Break,
                                                    Pmc960Line::DriveReady, Pmc960Line::Sensor};
            drive.setLine(kLines[n % 5], (n & 0x80) != 0);
            break;
        }
        case 0xFC: drive.powerUp(); break;
        case 0xFD: drive.setOverrunModel((n & 1) != 0); break;
        case 0xFE: step(std::chrono::microseconds(7 * n + 1)); break;
        default: pending += char(n); break; // 0xFF x
        }
        sent += drive.takeTransmitted().size();
    }
    flush();
    for (int k = 0; k < 50; ++k) drive.step(1ms);
    drive.receive("\x1b\r");
    drive.step(10ms);
    sent += drive.takeTransmitted().size();
    if (drive.state().program.size() > drive_core::pmc960::Pmc960Program::kCapacity) std::abort();
    (void)sent;
    return 0;
}
