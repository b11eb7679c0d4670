// The PMC-960's serial protocol, machine lines and power-up around the MPL interpreter. Decisions where the
// seed is silent are listed in DECISIONS.md next to this file.
#include "pmc960_drive.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace drive_core::pmc960 {

namespace {
constexpr char kAttention = 0x1D, kEsc = 0x1B, kLf = 0x0A, kBs = 0x08, kDel = 0x7F;
constexpr int kCharactersPerMs = 20; // interpreter speed: "most commands take less than 1 ms" (L243)

int baudFor(std::int64_t thb) {
    static constexpr int kRates[] = {9600, 38400, 19200, 9600, 4800, 2400, 1200, 600, 300};
    return thb >= 0 && thb <= 8 ? kRates[thb] : 9600;
}
} // namespace

Pmc960Drive::Pmc960Drive() {
    powerUp();
}

void Pmc960Drive::powerUp() {
    m_time = Microseconds{0};
    m_received.clear();
    m_checksum = 0; // power-up value 0 (digest §4.8, inferred)
    reset(true);
}

void Pmc960Drive::reset(bool powerCycle) {
    const bool generic = powerCycle && m_state.lines.estop; // ESTOP' held at power-up (L875)
    m_state.table.load(generic);
    m_state.reg = Pmc960Registers{};
    m_state.snapshot = Pmc960Snapshot{};
    m_state.motion.reset();
    m_state.applyTable();
    m_state.motion.setTripPoint(2048);
    if (const auto image = Pmc960Program::epromProgram(m_eprom)) m_state.program.assign(*image);
    m_interpreter.abort();
    m_mode = Mode::Command;
    m_attention = false;
    // One drive on RS-232 talks from power-up; on a bus every drive would, so there each waits to be selected.
    // A software reset keeps the choice the host made (DECISIONS.md, "Multi-axis bus").
    if (powerCycle || !m_onBus) m_talker = !m_onBus;
    m_heldError.reset();
    m_estopStopping = false;
    const std::int64_t thb = m_state.table.inUse("THB");
    if (powerCycle) {
        m_uart.reset(baudFor(thb));
        m_established = thb != 0;
    }
    const char label = char(m_state.table.inUse("TLP"));
    const bool skipRoutine = generic || m_state.lines.estop || m_state.lines.fault || m_state.lines.breakLine;
    if (label != 0 && !skipRoutine && m_interpreter.start(label)) return; // its end prompts
    prompt();
}

void Pmc960Drive::joinBus(char id) {
    m_state.table.set("THI", id);
    m_onBus = true;
}

void Pmc960Drive::receive(std::string_view bytes) {
    m_received.append(bytes);
}

std::string Pmc960Drive::takeTransmitted() {
    return m_uart.takeSent();
}

void Pmc960Drive::overrunStep(std::int64_t dt_us) {
    m_wireCredit += double(dt_us) * m_uart.baud() / 10.0 / 1e6;
    const std::int64_t now = m_time.count();
    // The firmware reads the buffer when it polls: not while busy after a trigger, and while a program
    // runs only to look for ESC and <attn>.
    auto polling = [this, now] {
        const bool program = m_interpreter.running() && m_interpreter.wait() == Pmc960Wait::None &&
                             m_mode == Mode::Command && m_established;
        return now >= m_busyUntil_us && (!program || m_holding == kEsc || m_holding == kAttention || m_attention);
    };
    std::size_t landed = 0;
    while (landed < m_received.size() && m_wireCredit >= 1) {
        if (m_holdingFull) ++m_overruns; // the character in the buffer is lost for ever
        m_holding = m_received[landed++];
        m_holdingFull = true;
        m_wireCredit -= 1;
        if (polling()) { // the firmware is polling: it reads at once
            m_holdingFull = false;
            inputByte(m_holding);
            if (m_mode == Mode::Command && (m_holding == '+' || m_holding == '-'))
                m_busyUntil_us = now + kBusyAfterTrigger_us;
        }
    }
    m_received.erase(0, landed);
    if (m_received.empty()) m_wireCredit = std::min(m_wireCredit, 1.0);
    if (m_holdingFull && polling()) {
        m_holdingFull = false;
        inputByte(m_holding);
    }
}

void Pmc960Drive::step(Microseconds dt) {
    if (m_overrunModel) {
        std::int64_t left = dt.count();
        if (left == 0) overrunStep(0);
        while (left > 0) {
            const std::int64_t slice = std::min<std::int64_t>(left, 100);
            tick(slice);
            overrunStep(slice);
            left -= slice;
        }
        m_uart.advance(dt);
        return;
    }
    // The SCI is polled: while a program runs (and waits for nothing) the next byte stays in the UART and
    // flow control holds the host (L2564), unless it is ESC or <attn>, which the PMC watches for.
    std::size_t i = 0;
    while (i < m_received.size()) {
        const char c = m_received[i];
        const bool held = m_talker && m_interpreter.running() && m_interpreter.wait() == Pmc960Wait::None &&
                          m_mode == Mode::Command && m_established && !m_attention && c != kEsc && c != kAttention;
        if (held) break;
        ++i;
        inputByte(c);
        if (m_interpreter.running() && m_interpreter.wait() == Pmc960Wait::None) tick(0);
    }
    m_received.erase(0, i);
    std::int64_t left = dt.count();
    if (left == 0) tick(0);
    while (left > 0) {
        const std::int64_t slice = std::min<std::int64_t>(left, 1000);
        tick(slice);
        left -= slice;
        if (!m_received.empty() && !(m_interpreter.running() && m_interpreter.wait() == Pmc960Wait::None)) {
            step(Microseconds{0}); // bytes a program held can be read now
        }
    }
    m_uart.advance(dt);
}

void Pmc960Drive::tick(std::int64_t dt_us) {
    m_time += Microseconds{dt_us};
    const std::int64_t now = m_time.count();
    m_state.motion.setStopTorque(double(m_state.reg.torque));
    if (dt_us > 0 && m_state.motion.step(double(dt_us) / 1e6)) { // PSJ overflow: IDLE and #E1 (L223)
        raise(0xE1);
        m_state.motion.setMode(0);
    }
    if (m_state.softwareLimits && m_state.motion.moving()) { // a software limit stops at TUB
        const Pmc960Units units = m_state.units();
        const double position = m_state.motion.commanded_counts();
        const double velocity = m_state.motion.referenceVelocity_cps();
        if ((velocity > 0 && position >= units.position_counts(double(m_state.reg.limitForward))) ||
            (velocity < 0 && position <= units.position_counts(double(m_state.reg.limitReverse))))
            m_state.motion.stop(units.maximumAccel_cps2());
    }
    if (m_estopStopping && !m_state.motion.moving()) {
        m_state.motion.setMode(0);
        m_estopStopping = false;
    }
    m_interpreter.poll(now);
    if (m_interpreter.running()) {
        const int budget =
            dt_us == 0 ? kCharactersPerMs : int(std::max<std::int64_t>(1, dt_us * kCharactersPerMs / 1000));
        m_interpreter.run(budget);
    }
    if (m_mode == Mode::Stream && now >= m_nextStream_us) {
        send("\r\n" + m_interpreter.display(m_streamCommand, '!'));
        m_nextStream_us = now + m_streamPeriod_us;
    }
}

void Pmc960Drive::inputByte(char c) {
    if (m_attention) {
        m_attention = false;
        if (std::islower(static_cast<unsigned char>(c))) { // a status poll: never in the checksum
            if (m_talker) poll(c);
            return;
        }
        if (c == kAttention && m_state.format().input() == NumberFormat::Binary) { // doubled 1DH = data
            if (!m_talker) return;
            m_checksum = std::uint16_t(m_checksum + 0x1D); // counted once (digest §4.8)
            deliver(c);
            return;
        }
        // <attn><ID>: talker or listener, not counted. A talker on a bus that another ID deselects turns its
        // RS-422 drivers off: what it had not sent yet never reaches the line (L2555).
        const bool wasTalker = m_talker;
        m_talker = c == m_state.axisId();
        if (wasTalker && !m_talker && m_onBus) m_uart.discard();
        return;
    }
    if (c == kAttention) {
        m_attention = true;
        return;
    }
    if (!m_talker) return; // a listener acts only on <attn><ID>
    m_checksum = std::uint16_t(m_checksum + static_cast<unsigned char>(c));
    deliver(c);
}

void Pmc960Drive::deliver(char c) {
    if (!m_established) { // autobaud: any character breaks a program; a CR establishes the SCI (L843)
        if (m_interpreter.running()) m_interpreter.abort();
        if (c == '\r') {
            m_established = true;
            prompt();
        }
        return;
    }
    switch (m_mode) {
    case Mode::Stream: // any character ends a % display (L775)
        m_mode = Mode::Command;
        prompt();
        return;
    case Mode::Listing:
        if (c == kEsc) {
            m_mode = Mode::Command;
            prompt();
        } else if (c == kLf) {
            listNextLine();
        } else if (c == kBs || c == kDel) { // back to the line before the one shown
            const std::string& text = m_state.program.text();
            std::size_t start = m_listPosition;
            for (int lines = 0; start > 0 && lines < 3; --start)
                if (text[start - 1] == '\r' && ++lines == 2) break;
            m_listPosition = start;
            listNextLine();
        }
        return;
    case Mode::Editor: {
        const auto reply = m_editor.feed(c, m_state.format().echo());
        send(reply.output);
        if (reply.error != 0) {
            raise(reply.error);
        } else if (reply.done) {
            m_mode = Mode::Command;
            prompt();
        }
        return;
    }
    case Mode::Command: break;
    }
    // ESC aborts (L2535), but not as a data byte of a binary number: only 1DH has to be sent twice to be
    // taken as data (L1879), so a distance of 27 is I<00><00><00><00><1B>.
    if (c == kEsc && !m_interpreter.readingBinaryNumber()) {
        if (const int code = m_interpreter.escape()) raise(code);
        return;
    }
    if (m_interpreter.wait() != Pmc960Wait::None) { // read and ignored while waiting (L2535)
        if (c == '@') m_interpreter.grantStep();
        if (c == '\r') m_interpreter.contourReturn();
        return;
    }
    if (m_interpreter.running()) return;
    m_interpreter.feed(c);
}

void Pmc960Drive::poll(char letter) {
    std::string text;
    switch (letter) {
    case 'b': text = m_interpreter.display("SB", '!'); break;
    case 'f': text = m_interpreter.display("SF", '!'); break;
    case 'g': text = m_interpreter.display("G", '!'); break;
    case 'i': text = m_interpreter.display("I", '!'); break;
    case 'm': text = m_interpreter.display("SS", '!'); break;
    case 's': text = m_interpreter.display("SI", '!'); break;
    case 'v': text = m_interpreter.display("V", '!'); break;
    case 'h':
        text = m_state.format().number(m_checksum, 16);
        if (m_state.format().output() == NumberFormat::Decimal) text = std::to_string(m_checksum);
        m_checksum = 0;
        break;
    default: return; // not a poll letter: ignored
    }
    // chosen (digest §11.2 #23): in decimal and hex output a poll reply ends with CR so a host can find its
    // end; binary replies have a fixed width.
    if (m_state.format().output() != NumberFormat::Binary) text += '\r';
    send(text);
}

void Pmc960Drive::send(std::string_view bytes) {
    if (!m_established || !m_talker || bytes.empty()) return;
    m_uart.write(bytes);
}

void Pmc960Drive::prompt() {
    if (!m_established || !m_talker) return;
    std::string out;
    if (m_heldError) {
        out += "#" + Pmc960Format::hexDigits(*m_heldError, 2);
        m_heldError.reset();
    }
    if (m_state.format().echo()) out += std::string("\r\n") + m_state.axisId();
    out += '}';
    send(out);
}

void Pmc960Drive::takeSnapshot(int code) {
    const Pmc960Units units = m_state.units();
    Pmc960Snapshot& s = m_state.snapshot;
    s.velocity = std::llround(units.userVelocity(std::abs(m_state.motion.velocity_cps())));
    s.position = std::llround(units.userPosition(m_state.motion.actual_counts()));
    s.motionBits = m_state.motionBits();
    s.inputs = m_state.inputs;
    s.lastLabel = m_state.reg.lastLabel;
    s.commandCount = m_state.reg.commandCount;
    s.outputs = m_state.reg.outputs;
    s.mode = m_state.motion.mode();
    s.error = code;
}

void Pmc960Drive::raise(int code) {
    takeSnapshot(code);
    m_state.reg.lastError = code;
    const bool wasBusy = !m_interpreter.idle() || m_mode != Mode::Command;
    m_interpreter.abort();
    m_mode = Mode::Command;
    if (code >= 0xE0 && m_state.format().hostMode()) { // held until the next prompt; only the first (L2292)
        if (!m_heldError) m_heldError = code;
        if (wasBusy) prompt();
        return;
    }
    send("#" + Pmc960Format::hexDigits(code, 2));
    prompt();
}

void Pmc960Drive::commandDone() {
    if (m_mode == Mode::Command) prompt();
}

void Pmc960Drive::enterEditor(std::size_t cursor) {
    m_editor.start(cursor);
    m_mode = Mode::Editor;
}

void Pmc960Drive::listProgram(bool lineByLine) {
    m_listPosition = 0;
    if (lineByLine) {
        m_mode = Mode::Listing;
        listNextLine();
        return;
    }
    // chosen: each buffer line is sent after CR LF, then the prompt.
    const std::string& text = m_state.program.text();
    std::string out;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t cr = text.find('\r', start);
        const std::size_t end = cr == std::string::npos ? text.size() : cr;
        out += "\r\n" + text.substr(start, end - start);
        start = end + 1;
    }
    send(out);
    prompt();
}

void Pmc960Drive::listNextLine() {
    const std::string& text = m_state.program.text();
    if (m_listPosition >= text.size()) {
        m_mode = Mode::Command;
        prompt();
        return;
    }
    const std::size_t cr = text.find('\r', m_listPosition);
    const std::size_t end = cr == std::string::npos ? text.size() : cr;
    send("\r\n" + text.substr(m_listPosition, end - m_listPosition));
    m_listPosition = end + 1;
}

void Pmc960Drive::stream(std::string command, int period_ms) {
    m_mode = Mode::Stream;
    m_streamCommand = std::move(command);
    m_streamPeriod_us = std::int64_t(period_ms) * 1000;
    // The first value at once, sent here rather than by a tick: a program that streams runs inside a
    // tick, and a tick from here would run it again, streaming again, until the stack ran out (found by
    // pmc960_drive_fuzz; reproducer in tests/drive_core/pmc960/fuzz_corpus).
    send("\r\n" + m_interpreter.display(m_streamCommand, '!'));
    m_nextStream_us = m_time.count() + m_streamPeriod_us;
}

void Pmc960Drive::softwareReset() {
    reset(false);
}

void Pmc960Drive::autobaud() {
    // The simulator's line has no rate to find: autobaud succeeds at once, then the identifier (L1357).
    send(std::string("\r\n") + std::string(kFirmwareId));
    prompt();
}

void Pmc960Drive::emergencyStop() {
    m_state.motion.stop(m_state.units().maximumAccel_cps2()); // at TUB (L2065-2074)
}

} // namespace drive_core::pmc960
