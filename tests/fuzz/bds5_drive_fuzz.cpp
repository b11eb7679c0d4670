// libFuzzer target for the simulated BDS5's serial input (issue 3, "Bad input"): any byte sequence at the
// port, with time passing, faults and input pins in between, must get the drive's answer or be ignored —
// never a crash, a hang, an escaping exception or state that grows without bound. The same file is the
// body of bds5_fuzz_replay, which runs the corpus and the crash reproducers in every CTest build.
#include "drive_core/bds5/bds5_drive.h"

#include <algorithm>
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
//   0xFD n   receive the bytes since the last operation (n+1)*16 times over (floods)
//   0xFE n   step(7n + 1 us): sub-millisecond steps
//   0xFF x   receive the literal byte x
// Every other byte is received as it is. At the end ^X breaks any program, and what the transmitter still
// holds must be explained by what was typed and done (see Session::finish).
//
// An input costs what it asks for and no more (issue 20, item 12): every millisecond of drive time is a
// servo tick with the plant in it and every flooded line a command answered, so the harness adds no time
// of its own and an input gets at most 250 ms of drive time and 1 KB of flood in all (later time and flood
// operations do nothing). 1 KB reaches every bound of the drive's input handling: 80 characters a line
// (the 81st rings), 15 entries an instruction, 20 entries of ERR HIST, 30 macro segments, and 128 and
// more repeats of a short line (the coverage counters' top bucket). Beyond any flood the harness allows,
// 4 KB included: 16,000 characters of program memory (the input and its floods stay under 8 KB) and the
// transmitter's 4 KB compaction (250 ms carry at most 480 characters at 19200 baud). The replay runs every
// input under the same budget, corpus/bds5-long's too: its sessions without a CR reach the drive as their
// first KB of flood. The harness reads the transmitter's backlog instead of letting it drain, and a
// program that outruns the line shows itself in that backlog within the time the input gives it.

namespace {

using drive_core::Microseconds;
using drive_core::bds5::Bds5Drive;
using namespace std::chrono_literals;

constexpr std::size_t kMaxFlood = 1024;       // flooded bytes an input, in all
constexpr Microseconds kMaxDriveTime = 250ms; // simulated time an input, in all
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
        m_typed = true; // the next step takes them
    }

    // One step() call: what leaves the drive in dt is what the line carries at BAUD, 8N1 (ten bits a
    // character), plus one character of rounding credit.
    void step(Microseconds dt) {
        dt = std::min(dt, m_timeLeft);
        if (dt <= Microseconds{0}) return;
        m_timeLeft -= dt;
        const std::size_t before = m_drive.transmitBacklog();
        m_drive.step(dt);
        const std::string out = m_drive.takeTransmitted();
        const double carried = double(dt.count()) * m_drive.baudRate() / 10.0 / 1e6;
        if (double(out.size()) > carried + 2.0)
            fail("output faster than the baud rate", (long long)out.size(), dt.count());
        // What a step that takes typed bytes writes answers them (muted bytes leave unseen: count what
        // the line could carry). A listing is the size of what it lists, not of the line that asked.
        if (std::exchange(m_typed, false)) {
            const std::size_t written = m_drive.transmitBacklog() + std::size_t(carried) + 2;
            if (written > before) m_answered += written - before;
        }
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

    // Types ^X and lets the drive take it. Everything still queued must be explained by what was typed
    // and done: the answers the typed lines got (DUMP, PLAY, TPLAY and <BDS are kilobytes for five typed
    // bytes; three DUMPs outgrew a fixed ~128 characters a typed byte), what operations made the drive
    // say, and the program (the editor's P BEG END: a few characters a stored line). A backlog beyond
    // that grew by itself: a program's prints wait for the line (L4637), so a running one cannot queue
    // more. (A program's output in the step that takes typed bytes counts as their answer; an input that
    // gives the program time after typing shows it.)
    void finish() {
        receive("\x18");
        m_timeLeft = 1ms; // the ^X is taken whatever the input spent
        step(1ms);
        const std::size_t bound =
            m_answered + 128 * (m_received + m_operations) + 16 * m_drive.state().program.sizeChars() + 8192;
        if (m_drive.transmitBacklog() > bound)
            fail("transmit backlog grows without bound", (long long)m_drive.transmitBacklog(), (long long)bound);
    }

    Bds5Drive& drive() { return m_drive; }

private:
    Bds5Drive m_drive;
    std::size_t m_received = 0; // bytes given to receive()
    std::size_t m_sent = 0;     // bytes taken from takeTransmitted()
    std::size_t m_operations = 0;
    std::size_t m_answered = 0; // characters written by the steps that took typed bytes
    bool m_typed = false;       // bytes received and not yet taken by a step
    Microseconds m_timeLeft = kMaxDriveTime;
};

void run(const std::uint8_t* data, std::size_t size) {
    Session s;
    std::string pending; // plain bytes, handed to the drive before the next operation
    const auto flush = [&] {
        if (pending.empty()) return;
        s.receive(pending);
        pending.clear();
    };
    std::size_t floodLeft = kMaxFlood;
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
            for (std::size_t n = 0; n < times && flood.size() + pending.size() <= floodLeft; ++n)
                flood += pending;
            floodLeft -= flood.size();
            if (!flood.empty()) pending = std::move(flood);
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
    s.finish();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        run(data, size);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bds5_drive_fuzz: exception escaped the drive: %s\n", e.what());
        std::abort();
    } catch (...) {
        std::fprintf(stderr, "bds5_drive_fuzz: unknown exception escaped the drive\n");
        std::abort();
    }
    return 0;
}
