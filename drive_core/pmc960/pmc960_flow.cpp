// MPL program control: input conditions <hex>[:<mask>] (B F E Q U), the X/Y/Z loop counters, and the P
// command's entry into the editor and listings. Program execution itself is in pmc960_interpreter.cpp.
#include "pmc960_interpreter.h"

#include <cctype>

namespace drive_core::pmc960 {

namespace {
char upper(char c) {
    return char(std::toupper(static_cast<unsigned char>(c)));
}
bool isHexDigit(char c) {
    return std::isxdigit(static_cast<unsigned char>(c)) != 0;
}
} // namespace

bool Pmc960Interpreter::conditionHolds() const {
    if (m_digits.empty()) return true;
    auto hex = [](const std::string& s) {
        int v = 0;
        for (const char d : s)
            v = v * 16 + (std::isdigit(static_cast<unsigned char>(d)) ? d - '0' : upper(d) - 'A' + 10);
        return v;
    };
    const int pattern = hex(m_digits) & 0xFF;
    const int mask = m_colon ? hex(m_fraction) & 0xFF : 0xFF;
    const int active = m_state.inputs & 0xFF; // IN07'..IN00', 1 = asserted (L1083-1091)
    return ((active ^ pattern) & mask) == 0;
}

// B<label>[<hex>[:<mask>]][<sync>]<cr>, F..., E..., Q..., U... (L1075-1163, L2128-2138)
void Pmc960Interpreter::conditionArgument(char c) {
    const char cmd = m_command[0];
    if ((cmd == 'B' || cmd == 'F') && m_label == 0) {
        if (cmd == 'B' && c == '|') {
            m_label = char(m_state.table.inUse("TLB"));
            if (m_label == 0) m_label = '|';
            return;
        }
        if (!Pmc960Program::validLabel(c)) return fail(0xC5);
        m_label = c;
        return;
    }
    if (isHexDigit(c) && !m_synced) {
        std::string& digits = m_colon ? m_fraction : m_digits;
        if (digits.size() >= 2) return fail(0xA2);
        digits += c;
        return;
    }
    if (c == ':' && !m_colon && !m_digits.empty() && !m_synced) {
        m_colon = true;
        return;
    }
    if (c == ',' || c == ';') {
        m_synced = true;
        beginWait(c == ',' ? Pmc960Wait::MotionDone : Pmc960Wait::ConstantSpeed, false);
        return;
    }
    if (c != '\r') return fail(0xA2);
    const bool holds = conditionHolds();
    const bool program = m_source == Source::Program;
    switch (cmd) {
    case 'U':
        if (holds) return finish();
        return beginWait(Pmc960Wait::Until, true);
    case 'Q':
        if (program && holds) return endProgram();
        return finish();
    case 'E':
        if (!program) return fail(0xA1); // valid only in a program (L1146)
        if (!holds) return finish();
        if (m_calls.empty()) return endProgram(); // no caller: back to READY (digest §11.2 #4)
        m_pc = m_calls.back();
        m_calls.pop_back();
        resetCommand();
        return;
    default: break; // B F
    }
    if (!holds) return finish();
    const char label = m_label;
    if (!program) {
        if (!start(label)) return fail(0xC2);
        return;
    }
    if (cmd == 'F') {
        if (m_calls.size() >= kCallDepth) return fail(0x90); // depth not documented (digest §11.2 #6)
        m_calls.push_back(m_pc);
    }
    ++m_state.reg.commandCount;
    resetCommand();
    if (!jump(label)) fail(0xC2);
}

// L<label>[X|Y|Z]<count><cr> | L<cr> (L1300-1340; counter rule digest §5.4)
void Pmc960Interpreter::loopArgument(char c) {
    if (m_label == 0) {
        if (c == '\r') { // chosen: L<cr> resets every counter (the manual: "resets the counter")
            m_counters = {};
            return finish();
        }
        if (!Pmc960Program::validLabel(c)) return fail(0xC5);
        m_label = c;
        return;
    }
    const bool hexIn = m_state.format().input() != NumberFormat::Decimal;
    if (m_counter == 0 && !numberGiven() && std::isalpha(static_cast<unsigned char>(c)) && !(hexIn && isHexDigit(c))) {
        const char u = upper(c);
        if (u != 'X' && u != 'Y' && u != 'Z') return fail(0xC8);
        m_counter = u;
        return;
    }
    if (collectDigit(c, false)) return;
    if (c != '\r') return fail(0xA2);
    const std::int64_t count = numberGiven() ? number() : 0;
    if (count > 65535) return fail(0x90);
    const char label = m_label;
    if (m_source == Source::Sci) { // run <label>, <count> replacing the first loop count met
        const bool given = numberGiven();
        if (!start(label)) return fail(0xC2);
        if (given) m_loopOverride = count;
        return;
    }
    std::int64_t limit = count;
    if (m_loopOverride) {
        limit = *m_loopOverride;
        m_loopOverride.reset();
    }
    const std::size_t id = m_counter == 0 ? 0 : std::size_t(m_counter - 'W');
    std::uint32_t& counter = m_counters[id];
    counter = counter == 0 ? std::uint32_t(limit) : counter - 1;
    ++m_state.reg.commandCount;
    resetCommand();
    if (counter > 0 && !jump(label)) fail(0xC2);
}

// P{ | P<cr> | P<label> | P? | P! (L1398-1439)
void Pmc960Interpreter::programArgument(char c) {
    if (m_source == Source::Program) return fail(0xC6);
    if (c == '?' || c == '!') {
        resetCommand();
        m_sink.listProgram(c == '?');
        return;
    }
    if (m_state.reg.writeEnable == 0) return fail(0xD3);
    if (m_state.table.inUse("THP") != 0 && (m_state.inputs & 0x20) == 0) return fail(0xD3); // IN05'
    std::size_t cursor = 0;
    if (c == '\r') {
        cursor = m_state.program.size();
    } else if (c != '{') {
        const auto at = m_state.program.findLabel(c);
        if (!at) return fail(0xC2);
        cursor = *at;
    }
    resetCommand();
    m_sink.enterEditor(cursor);
}

} // namespace drive_core::pmc960
