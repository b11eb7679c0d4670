// libFuzzer target for the simulated BDS5's serial input (issue 3, "Bad input"): any byte sequence at the
// port, with time passing, faults and input pins in between, must get the drive's answer or be ignored —
// never a crash, a hang, an escaping exception or state that grows without bound. The same file is the
// body of bds5_fuzz_replay, which runs the corpus and the crash reproducers in every CTest build.
#include "drive_core/bds5/bds5_drive.h"

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>
#include <utility>

// The input is the byte stream at the port, with operations escaped by the bytes 0xF8-0xFF (so a plain
// text file is a session typed in one go; bytes 0xF8-0xFF reach the drive through 0xFF x):
//   0xF8 n   step(n+1 ms) in one call
//   0xF9 n   n+1 steps of 10 ms
//   0xFA n   setInput(n%16 + 1, n & 0x80)
//   0xFB n   raiseFault(n)
//   0xFC     powerUp()
//   0xFD n   receive the bytes since the last operation (n+1)*16 times over, at most 16 KB (floods)
//   0xFE n   step(7n + 1 us): sub-millisecond steps
//   0xFF x   receive the literal byte x
// Every other byte is received as it is. At the end 50 ms pass, ^X breaks any program, and the
// transmitter must drain within the backlog bound (see Session::finish); a session that leaves a program
// running is run twice, the second time with 10 s more before the ^X (see LLVMFuzzerTestOneInput).

namespace {

using drive_core::Microseconds;
using drive_core::bds5::Bds5Drive;
using drive_core::bds5::Bds5DriveMode;
using namespace std::chrono_literals;

constexpr std::size_t kMaxFlood = std::size_t(1) << 14;
constexpr Microseconds kExtraRun = 5s; // more program time for the outrun check (5 s of servo ticks
                                        // keep the fuzzer at a useful pace now the drive has physics)
constexpr Microseconds kExtraStep = 100ms;
// BDS5_FUZZ_TRACE=1 copies what the drive sends to stderr, to read a reproducer's session.
const bool kTrace = std::getenv("BDS5_FUZZ_TRACE") != nullptr;

[[noreturn]] void fail(const char* what, long long a = 0, long long b = 0) {
    std::fprintf(stderr, "bds5_drive_fuzz: invariant violated: %s (%lld, %lld)\n", what, a, b);
    std::abort();
}

class Session {
public:
    Session() { m_drive.powerUp(); }

    void receive(std::string_view bytes) {
        m_drive.receive(bytes);
        m_received += bytes.size();
    }

    // One step() call: what leaves the drive in dt is what the line carries at BAUD, 8N1 (ten bits a
    // character), plus one character of rounding credit.
    void step(Microseconds dt) {
        m_drive.step(dt);
        const std::string out = m_drive.takeTransmitted();
        const double carried = double(dt.count()) * m_drive.baudRate() / 10.0 / 1e6;
        if (double(out.size()) > carried + 2.0)
            fail("output faster than the baud rate", (long long)out.size(), dt.count());
        m_sent += out.size();
        if (kTrace) std::fwrite(out.data(), 1, out.size(), stderr);
        checkState();
    }

    void checkState() const {
        const auto& program = m_drive.state().program;
        if (program.sizeChars() > drive_core::bds5::kProgramCapacityChars)
            fail("program memory over capacity", (long long)program.sizeChars());
        std::size_t counted = 0;
        for (const std::string& line : program.lines())
            counted += line.size() + 1; // each line with its CR
        if (counted != program.sizeChars())
            fail("program size bookkeeping", (long long)counted, (long long)program.sizeChars());
        if (m_drive.state().errorHistory.size() > drive_core::bds5::kErrorHistorySize)
            fail("error history over 20 entries", (long long)m_drive.state().errorHistory.size());
    }

    // An operation that may make the drive talk without anything typed (a fault, a power-up).
    void countOperation() { ++m_operations; }

    struct Ending {
        std::size_t drained = 0;     // characters the transmitter still held after ^X
        bool programRunning = false; // a program was still running when the input ended
    };

    // Lets 50 ms and then `extra` pass, types ^X and lets the transmitter empty. Everything still queued
    // must be explained by what was typed and done (echo, answers: ERR HIST is the wordiest, ~60
    // characters a typed byte) and by the program (a listing, the editor's P BEG END: a few characters a
    // stored one); a backlog beyond that grew by itself.
    Ending finish(Microseconds extra) {
        for (int i = 0; i < 50; ++i)
            step(1ms);
        Ending ending;
        const auto mode = m_drive.mode();
        ending.programRunning = mode == Bds5DriveMode::Running || mode == Bds5DriveMode::Monitor;
        for (; extra > Microseconds{0}; extra -= kExtraStep)
            step(kExtraStep);
        receive("\x18");
        step(1ms);
        const std::size_t bound =
            128 * (m_received + m_operations) + 16 * m_drive.state().program.sizeChars() + 8192;
        while (m_drive.transmitting()) {
            const std::size_t before = m_sent;
            step(1s);
            ending.drained += m_sent - before;
            if (ending.drained > bound)
                fail("transmit backlog grows without bound", (long long)ending.drained, (long long)bound);
        }
        return ending;
    }

    Bds5Drive& drive() { return m_drive; }

private:
    Bds5Drive m_drive;
    std::size_t m_received = 0; // bytes given to receive()
    std::size_t m_sent = 0;     // bytes taken from takeTransmitted()
    std::size_t m_operations = 0;
};

Session::Ending run(const std::uint8_t* data, std::size_t size, Microseconds extra) {
    Session s;
    std::string pending; // plain bytes, handed to the drive before the next operation
    const auto flush = [&] {
        if (!pending.empty()) s.receive(std::exchange(pending, {}));
    };
    std::size_t i = 0;
    const auto arg = [&]() -> std::uint8_t { return i < size ? data[i++] : 0; };
    while (i < size) {
        const std::uint8_t b = data[i++];
        if (b < 0xF8) {
            pending.push_back(char(b));
            continue;
        }
        if (b == 0xFF) {
            pending.push_back(char(arg()));
            continue;
        }
        if (b == 0xFD) {
            const std::size_t times = (std::size_t(arg()) + 1) * 16;
            std::string flood;
            for (std::size_t n = 0; n < times && flood.size() + pending.size() <= kMaxFlood; ++n)
                flood += pending;
            pending = std::move(flood);
        }
        flush();
        s.countOperation();
        switch (b) {
        case 0xF8:
            s.step(Microseconds(1000 * (arg() + 1)));
            break;
        case 0xF9:
            for (int n = arg(); n >= 0; --n)
                s.step(10ms);
            break;
        case 0xFA: {
            const std::uint8_t n = arg();
            s.drive().setInput(n % 16 + 1, (n & 0x80) != 0);
            break;
        }
        case 0xFB:
            s.drive().raiseFault(arg());
            break;
        case 0xFC:
            s.drive().powerUp();
            break;
        case 0xFD:
            break; // received above
        case 0xFE:
            s.step(Microseconds(7 * arg() + 1));
            break;
        default:
            break;
        }
    }
    flush();
    return s.finish(extra);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        // A running program's prints wait for the line (L4637), so what is queued when it is broken
        // does not depend on how long it ran. The same session run again with 10 s more of program
        // time must leave about the same backlog; more means the program outruns the line.
        const Session::Ending ending = run(data, size, Microseconds{0});
        if (ending.programRunning) {
            const Session::Ending longer = run(data, size, kExtraRun);
            if (longer.drained > ending.drained + 4096)
                fail("a running program's output outruns the line", (long long)longer.drained,
                     (long long)ending.drained);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bds5_drive_fuzz: exception escaped the drive: %s\n", e.what());
        std::abort();
    } catch (...) {
        std::fprintf(stderr, "bds5_drive_fuzz: unknown exception escaped the drive\n");
        std::abort();
    }
    return 0;
}
