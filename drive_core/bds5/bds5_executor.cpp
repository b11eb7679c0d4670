// BDS5 main-task execution and control flow (L3728-4103, Table 4.2, App. F).
#include "bds5_executor.h"

#include "drive_core/catalog/bds5_catalog.h"

#include <chrono>

namespace drive_core::bds5 {

using namespace std::chrono_literals;

namespace {
constexpr int kMaxLinesPerAdvance = 10000; // a runaway loop of zero-cost lines cannot hang a tick
}

Microseconds Bds5Executor::costOf(const LexedLine& line) {
    if (line.entries.empty()) return 1000us; // a comment line: read like a label line (chosen)
    const std::string& w = line.entries.front().text;
    if (w.back() == '$') return 1000us;
    if (w == "GOTO" || w == "GOSUB") return 1600us;
    if (w == "RET") return 800us;
    if (w == "TIL") return 2600us;
    if (w == "?") return 4000us;
    if (w == "P" || w == "PA" || w == "PS" || w == "PAS" || w == "R" || w == "RS") return 3500us;
    if (w == "IF" || w == "ELIF" || w == "ELSE" || w == "ENDIF") return 1300us; // 9 ms for 7 lines with bodies
    if (w == "ZPE") return 1000us;
    if (w == "NORM") return 2000us;
    if (w == "MA" || w == "MI") return 5500us;
    if (w == "JT" || w == "JF") return 5800us;
    if (w.find('=') != std::string::npos || line.entries.size() == 2) return 2000us; // X1=X2+1: 1.7-2.3 ms
    return 2000us;
}

void Bds5Executor::start(int line, Microseconds now) {
    m_running = true;
    m_pc = line;
    m_busyUntil = now;
    m_gosub.clear();
    m_ifDepth = 0;
}

ProgramStop Bds5Executor::advance(Microseconds now, std::string& out, std::optional<Bds5Error>& error) {
    for (int n = 0; m_running && m_busyUntil <= now && n < kMaxLinesPerAdvance; ++n) {
        const ProgramStop stop = executeLine(out, error);
        if (stop != ProgramStop::Running) {
            m_running = false;
            return stop;
        }
    }
    return ProgramStop::Running;
}

ProgramStop Bds5Executor::fail(Bds5Error e, std::optional<Bds5Error>& out) {
    const auto* info = catalog::bds5::findError(e.code);
    logError(m_state, e.code);
    out = std::move(e);
    // Severity 1 is a message only; 2 and above break the program (Table D.1).
    if (info && info->severity <= catalog::bds5::Severity::Warning && out->code != 53) return ProgramStop::Running;
    return ProgramStop::Error;
}

ProgramStop Bds5Executor::executeLine(std::string& out, std::optional<Bds5Error>& error) {
    const Bds5Program& program = m_state.program;
    if (m_pc < 1 || m_pc > program.lineCount()) return ProgramStop::Break; // ran off the end: as END
    const int line = m_pc;
    const LexedLine& lexed = program.lexed(line);
    m_busyUntil += costOf(lexed); // lines follow one another without gaps: simulated time is exact
    ++m_pc;
    if (lexed.entries.empty()) {
        // An empty lexed line is a comment, or a line with quote damage: lex it again for the error.
        auto again = lexLine(program.line(line));
        if (auto* e = std::get_if<Bds5Error>(&again)) {
            e->line = line;
            return fail(*e, error);
        }
        return ProgramStop::Running;
    }
    if (Bds5Program::numericLabel(lexed)) return ProgramStop::Running; // a label line is a 1 ms no-op
    if (const auto dedicated = Bds5Program::dedicatedLabel(lexed)) {
        // Main-level labels fall through; another task's code is never entered sequentially (chosen).
        const bool mainLevel = *dedicated == DedicatedLabel::PowerUp || *dedicated == DedicatedLabel::Auto ||
                               *dedicated == DedicatedLabel::Manual;
        return mainLevel ? ProgramStop::Running : ProgramStop::Break;
    }

    const Outcome o = m_interpreter.execute(lexed.entries, ExecContext{Origin::Program, line}, out);
    if (o.error) return fail(*o.error, error);
    switch (o.flow) {
    case Flow::Next: return ProgramStop::Running;
    case Flow::Goto:
    case Flow::Gosub: {
        const auto target = program.labelLine(o.target);
        if (!target) return fail(Bds5Error{70, std::to_string(o.target), line}, error);
        if (o.flow == Flow::Gosub) {
            if (int(m_gosub.size()) >= kMaxGosubLevels) return fail(Bds5Error{118, lexed.entries[0].text, line}, error);
            m_gosub.push_back(Frame{m_pc, m_ifDepth});
        }
        m_ifDepth = 0; // jumping out of IF blocks closes them (L4093-4103)
        m_pc = *target;
        return ProgramStop::Running;
    }
    case Flow::Return:
        if (m_gosub.empty()) return fail(Bds5Error{119, "RET", line}, error);
        m_pc = m_gosub.back().returnLine;
        m_ifDepth = m_gosub.back().ifDepth;
        m_gosub.pop_back();
        return ProgramStop::Running;
    case Flow::Repeat: m_pc = line; return ProgramStop::Running;
    case Flow::Dwell: m_busyUntil += std::chrono::milliseconds(o.target); return ProgramStop::Running;
    case Flow::If:
    case Flow::Elif: {
        if (o.flow == Flow::Elif) { // reached in sequence: the block before it ran, skip to ENDIF
            if (m_ifDepth == 0) return fail(Bds5Error{116, "ELIF", line}, error);
            const auto end = findBlockEnd(line, true);
            if (!end) return fail(Bds5Error{115, "ELIF", line}, error);
            m_pc = *end;
            return ProgramStop::Running;
        }
        ++m_ifDepth;
        int at = line;
        bool taken = o.condition;
        while (!taken) { // try the ELIFs in turn, then the ELSE; every condition costs its line's time
            const auto next = findBlockEnd(at, false);
            if (!next) return fail(Bds5Error{115, "IF", line}, error);
            const LexedLine& l = program.lexed(*next);
            const std::string& w = l.entries.front().text;
            at = *next;
            if (w == "ELIF") {
                m_busyUntil += costOf(l);
                const Outcome c = m_interpreter.execute(l.entries, ExecContext{Origin::Program, at}, out);
                if (c.error) return fail(*c.error, error);
                taken = c.condition;
            } else {
                taken = true; // ELSE runs its block; ENDIF closes with nothing run
                if (w == "ENDIF") {
                    m_pc = at; // execute the ENDIF line itself (it shows in a trace)
                    return ProgramStop::Running;
                }
            }
        }
        m_pc = at + 1;
        return ProgramStop::Running;
    }
    case Flow::Else: {
        if (m_ifDepth == 0) return fail(Bds5Error{116, "ELSE", line}, error);
        const auto end = findBlockEnd(line, true);
        if (!end) return fail(Bds5Error{115, "ELSE", line}, error);
        m_pc = *end;
        return ProgramStop::Running;
    }
    case Flow::Endif:
        if (m_ifDepth == 0) return fail(Bds5Error{116, "ENDIF", line}, error);
        --m_ifDepth;
        return ProgramStop::Running;
    case Flow::End:
    case Flow::Break: return ProgramStop::Break;
    case Flow::Kill: return ProgramStop::Kill;
    case Flow::Stop: return ProgramStop::Running; // S in a program stops motion only (motion: issue 4)
    case Flow::Run: { // v3: RUN inside a program restarts at the label (L9307)
        const auto target = o.target < 0 ? std::optional<int>(1) : program.labelLine(o.target);
        if (!target) return fail(Bds5Error{70, std::to_string(o.target), line}, error);
        start(*target, m_busyUntil);
        return ProgramStop::Running;
    }
    case Flow::Load:
    case Flow::List: return fail(Bds5Error{53, lexed.entries[0].text, line}, error);
    }
    return ProgramStop::Running;
}

std::optional<int> Bds5Executor::findBlockEnd(int from, bool toEndif) const {
    const Bds5Program& program = m_state.program;
    int depth = 0;
    for (int l = from + 1; l <= program.lineCount(); ++l) {
        const LexedLine& lexed = program.lexed(l);
        if (lexed.entries.empty()) continue;
        const std::string& w = lexed.entries.front().text;
        if (w == "IF") ++depth;
        else if (w == "ENDIF") {
            if (depth == 0) return l;
            --depth;
        } else if (depth == 0 && !toEndif && (w == "ELIF" || w == "ELSE")) return l;
    }
    return std::nullopt;
}

} // namespace drive_core::bds5
