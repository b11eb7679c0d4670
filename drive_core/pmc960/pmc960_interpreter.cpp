// The MPL character-stream machine: command letters, waits, labels, program flow (B F E Q L), and the
// dispatch of arguments to the command families in pmc960_commands.cpp.
#include "pmc960_interpreter.h"

#include <cctype>
#include <cmath>

namespace drive_core::pmc960 {

namespace {
char upper(char c) {
    return char(std::toupper(static_cast<unsigned char>(c)));
}
bool isHexDigit(char c) {
    return std::isxdigit(static_cast<unsigned char>(c)) != 0;
}
} // namespace

void Pmc960Interpreter::feed(char c) {
    if (m_running || m_wait != Pmc960Wait::None) return; // read and ignored (L2535)
    m_source = Source::Sci;
    // Binary numbers (NUL and data bytes) are not echoed: they are no characters a terminal shows.
    const bool binaryData = m_state.format().input() == NumberFormat::Binary && (m_binaryBytes > 0 || c == '\0');
    if (m_state.format().echo() && c != '\r' && !binaryData) m_sink.send(std::string_view(&c, 1));
    dispatch(c);
}

int Pmc960Interpreter::run(int budget) {
    int used = 0;
    while (m_running && m_wait == Pmc960Wait::None && used < budget) {
        if (m_pc >= m_state.program.size()) { // end of the buffer: back to READY (digest §11.2 #5)
            endProgram();
            break;
        }
        const char c = m_state.program.text()[m_pc++];
        ++used;
        m_source = Source::Program;
        if (m_state.format().trace()) m_sink.send(c == '\r' ? std::string_view("\r\n") : std::string_view(&c, 1));
        dispatch(c);
    }
    return used;
}

void Pmc960Interpreter::poll(std::int64_t now_us) {
    m_now_us = now_us;
    if (m_wait == Pmc960Wait::None || !waitSatisfied()) return;
    const Pmc960Wait was = m_wait;
    m_wait = Pmc960Wait::None;
    m_stepGranted = false;
    if (m_waitEndsCommand) {
        m_waitEndsCommand = false;
        finish();
    } else if (m_source == Source::Sci && was != Pmc960Wait::SingleStep) {
        m_sink.send("}"); // the sync handshake (L2512)
    }
}

void Pmc960Interpreter::grantStep() {
    if (m_wait == Pmc960Wait::SingleStep) m_stepGranted = true;
}

void Pmc960Interpreter::contourReturn() {
    if (m_wait != Pmc960Wait::ContourReady || m_source != Source::Sci) return;
    m_wait = Pmc960Wait::None;
    finish();
}

bool Pmc960Interpreter::waitSatisfied() const {
    switch (m_wait) {
    case Pmc960Wait::None: return true;
    case Pmc960Wait::MotionDone: return !m_state.motion.moving();
    case Pmc960Wait::ConstantSpeed: return m_state.motion.atConstantSpeed();
    case Pmc960Wait::Dwell: return m_now_us >= m_waitUntil_us;
    case Pmc960Wait::Until: return conditionHolds();
    case Pmc960Wait::SingleStep: return m_stepGranted;
    case Pmc960Wait::ContourReady: return !m_state.motion.full();
    case Pmc960Wait::CamSegment: return !m_state.motion.camHold();
    }
    return true;
}

void Pmc960Interpreter::beginWait(Pmc960Wait wait, bool endsCommand) {
    m_wait = wait;
    m_waitEndsCommand = endsCommand;
    poll(m_now_us); // already satisfied: the handshake goes out at once (L2531)
}

int Pmc960Interpreter::escape() {
    int code = 0;
    switch (m_wait) {
    case Pmc960Wait::MotionDone:
    case Pmc960Wait::ConstantSpeed: code = 0xB5; break;
    case Pmc960Wait::Dwell: code = 0xD0; break;
    case Pmc960Wait::Until: code = 0xD6; break; // the table's D6, not 7.19's D0 (digest §11.2 #7)
    case Pmc960Wait::SingleStep: code = 0xD5; break;
    case Pmc960Wait::ContourReady: code = 0xD7; break;
    case Pmc960Wait::CamSegment: code = 0x89; break; // BREAK while Cam waited for the ^ synchronisation
    case Pmc960Wait::None:
        if (m_running)
            code = 0xC4;
        else if (m_phase != Phase::Idle)
            code = 0xD2;
        break;
    }
    abort();
    return code;
}

void Pmc960Interpreter::resetCommand() {
    m_phase = Phase::Idle;
    m_command.clear();
    clearNumber();
    m_sign = 0;
    m_label = 0;
    m_counter = 0;
    m_triggered = false;
    m_lineStarted = false;
    m_synced = false;
    m_register = 0;
    m_gainApplied = false;
    m_promptAtCr = false;
}

void Pmc960Interpreter::abort() {
    resetCommand();
    m_running = false;
    m_calls.clear();
    m_wait = Pmc960Wait::None;
    m_waitEndsCommand = false;
    m_stepGranted = false;
    m_loopOverride.reset();
}

bool Pmc960Interpreter::start(char label) {
    abort();
    return jump(label);
}

void Pmc960Interpreter::endProgram() {
    abort();
    m_sink.commandDone();
}

bool Pmc960Interpreter::jump(char label) {
    const auto at = m_state.program.findLabel(label);
    if (!at) return false;
    m_pc = *at;
    m_running = true;
    return true;
}

void Pmc960Interpreter::finish() {
    const bool program = m_source == Source::Program;
    resetCommand();
    if (program)
        ++m_state.reg.commandCount;
    else
        m_sink.commandDone();
}

void Pmc960Interpreter::fail(int code) {
    m_sink.raise(code); // the drive aborts this interpreter, reports and prompts
}

void Pmc960Interpreter::clearNumber() {
    m_digits.clear();
    m_fraction.clear();
    m_colon = false;
    m_binaryGiven = false;
    m_binary = 0;
    m_binaryBytes = 0;
}

std::int64_t Pmc960Interpreter::number() const {
    if (m_binaryGiven) return m_binary;
    const int base = m_hexNumber ? 16 : 10;
    std::int64_t v = 0;
    for (const char c : m_digits) {
        v = v * base + (std::isdigit(static_cast<unsigned char>(c)) ? c - '0' : upper(c) - 'A' + 10);
        if (v > (std::int64_t(1) << 40)) return v; // far out of every range
    }
    return v;
}

// Binary input (L1864-1904): NUL, then 1, 2 or 4 bytes MSB first; the width is fixed by the command.
int Pmc960Interpreter::binaryWidth() const {
    const std::string& k = m_command;
    if (k == "I" || k == "G" || k == "N" || k == "SL" || k == "C") return 4;
    if (k == "SM" || k == "SV" || k == "SW" || k == "SP" || k == "TG") return 1; // TGP..TGL are read as TG
    if (k.size() == 3 && k[0] == 'T' && k[1] == 'H' && k != "THA") return 1;
    return 2; // V (16 bits per the example), A J H D L SF SD ST OA OB (chosen, digest §4.9)
}

bool Pmc960Interpreter::collectDigit(char c, bool hexAlways) {
    const NumberFormat in = m_state.format().input();
    if (m_binaryBytes > 0) {
        m_binary = (m_binary << 8) | static_cast<unsigned char>(c);
        if (--m_binaryBytes == 0) m_binaryGiven = true;
        return true;
    }
    if (in == NumberFormat::Binary && c == '\0' && !hexAlways) {
        m_binary = 0;
        m_binaryBytes = binaryWidth();
        return true;
    }
    const bool hex = hexAlways || in != NumberFormat::Decimal;
    m_hexNumber = hex;
    if (std::isdigit(static_cast<unsigned char>(c)) || (hex && isHexDigit(c))) {
        if (m_colon)
            m_fraction += c;
        else
            m_digits += c;
        return true;
    }
    return false;
}

void Pmc960Interpreter::dispatch(char c) {
    m_lastChar = c;
    switch (m_phase) {
    case Phase::Idle:
        if (c == '\r') {
            if (m_source == Source::Sci) m_sink.commandDone();
            return;
        }
        if (c == ' ' || c == '.') return; // filler (L926)
        if (c == '@') {
            m_phase = Phase::Label;
            return;
        }
        if (std::isalpha(static_cast<unsigned char>(c))) {
            m_command = std::string(1, upper(c));
            static constexpr std::string_view kPlain = "ABCDEFGHIJLNPQRUV";
            m_phase = kPlain.find(m_command[0]) != std::string_view::npos ? Phase::Arguments : Phase::Letters;
            if (m_command == "K" || m_command == "M" || m_command[0] >= 'W') return fail(0xA1);
            if (m_command == "R" && m_source == Source::Sci) beginWait(Pmc960Wait::ContourReady, false); // R}
            return;
        }
        fail(0xA1);
        return;
    case Phase::Label:
        if (c == '\r') {
            resetCommand();
            if (m_source == Source::Sci) m_sink.commandDone();
            return;
        }
        m_promptAtCr = m_source == Source::Sci;
        m_phase = Phase::SkipLine;
        if (m_source == Source::Program) labelPassed(c);
        return;
    case Phase::SkipLine:
        if (c == '\r') {
            const bool prompt = m_promptAtCr;
            resetCommand();
            if (prompt) m_sink.commandDone();
        }
        return;
    case Phase::Letters: letter(c); return;
    case Phase::Arguments: argument(c); return;
    case Phase::Stream:
        if (std::isdigit(static_cast<unsigned char>(c))) {
            m_digits += c;
            return;
        }
        if (c == '\r') {
            const int period = m_digits.empty() ? 100 : int(std::min<std::int64_t>(number(), 65535));
            const std::string command = m_command;
            resetCommand();
            m_sink.stream(command, std::max(period, 1));
            return;
        }
        fail(0xA2);
        return;
    }
}

void Pmc960Interpreter::labelPassed(char label) {
    m_state.reg.lastLabel = label;
    m_state.reg.commandCount = 0;
    if (m_state.format().singleStep()) beginWait(Pmc960Wait::SingleStep, false);
}

void Pmc960Interpreter::letter(char c) {
    const char u = upper(c);
    const std::string& k = m_command;
    const bool display = c == '?' || c == '!';
    if (k == "O") {
        if (u != 'A' && u != 'B') return fail(0xA1);
        m_command += u;
    } else if (k == "S") {
        static constexpr std::string_view kSub = "BDEFILMNPSTVWY";
        if (kSub.find(u) == std::string_view::npos) return fail(0xA1);
        m_command = u == 'Y' ? "SP" : "S" + std::string(1, u); // SY: the contour example's SP (§11.2 #20)
    } else if (k == "T") {
        if (display) {
            m_sink.send(this->display("T", c));
            return finish();
        }
        static constexpr std::string_view kSub = "FGHLU";
        if (kSub.find(u) == std::string_view::npos) return fail(0xA1);
        m_command += u;
        if (u == 'H' || u == 'L' || u == 'U') return; // a third letter follows
    } else {                                          // TH TL TU
        if (display) {
            m_sink.send(this->display(k, c));
            return finish();
        }
        const std::string_view sub = k == "TH" ? "ABCILMPRS" : k == "TL" ? "BPV" : "ABHPSV";
        if (sub.find(u) == std::string_view::npos) return fail(0xA1);
        m_command += u;
    }
    m_phase = Phase::Arguments;
}

bool Pmc960Interpreter::displayChar(char c) {
    if (m_lineStarted || numberGiven()) return false;
    if (c == '?' || c == '!' || c == '&') {
        const std::string text = display(m_command, c);
        if (text.empty()) {
            fail(0xA2);
            return true;
        }
        m_sink.send(text);
        finish();
        return true;
    }
    if (c == '%' && !display(m_command, '!').empty()) {
        m_phase = Phase::Stream;
        return true;
    }
    return false;
}

void Pmc960Interpreter::argument(char c) {
    if (m_binaryBytes > 0) { // inside a binary number every byte is data
        collectDigit(c, false);
        // A binary number has no terminator (L1877): its last byte ends the command as <cr> would, so
        // I<00><4 bytes> sets the distance in 7 bytes (L1891-1903) as V<00><2 bytes> sets the speed in 4
        // (L1886-1888). chosen: the commands whose sign is written after the number as that number's own
        // sign — G (L1169), N (L1346), OA (L1371), SL (L1536) — still read it, a binary number having none;
        // G, OA and SL then end at <cr>, N at its sign, as in ASCII.
        const bool signFollows = m_command == "G" || m_command == "N" || m_command == "OA" || m_command == "SL";
        if (m_binaryGiven && !signFollows) argument('\r');
        return;
    }
    const std::string& k = m_command;
    if (k != "P" && displayChar(c)) return;
    const bool first = !m_lineStarted;
    m_lineStarted = true;
    switch (k[0]) {
    case 'I':
    case 'J':
    case 'G':
    case 'H':
    case 'N': return motionArgument(c, first);
    case 'B':
    case 'F':
    case 'E':
    case 'Q':
    case 'U': return conditionArgument(c);
    case 'L': return loopArgument(c);
    case 'P': return programArgument(c);
    case 'C': return camArgument(c, first);
    case 'R': return contourArgument(c);
    default: break;
    }
    if (k.size() == 3 && k[1] == 'G') return gainsArgument(c);
    if (k == "TG") return gainsArgument(c);
    valueArgument(c, first);
}

} // namespace drive_core::pmc960
