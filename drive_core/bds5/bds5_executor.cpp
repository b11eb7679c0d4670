// BDS5 task scheduling and control flow (L3728-4103, L4551-5025, Tables 4.2 and 4.5, App. F).
#include "bds5_executor.h"

#include "drive_core/catalog/bds5_catalog.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <utility>

namespace drive_core::bds5 {

using namespace std::chrono_literals;

namespace {
// Switches and inputs the executor reads for every line it runs, resolved once.
struct PollRefs {
    catalog::bds5::VariableRef multi, cycle, manual, pext, regkhz;
};
const PollRefs& pollRefs() {
    static const PollRefs r{*catalog::bds5::findVariable("MULTI"), *catalog::bds5::findVariable("CYCLE"),
                            *catalog::bds5::findVariable("MANUAL"), *catalog::bds5::findVariable("PEXT"),
                            *catalog::bds5::findVariable("REGKHZ")};
    return r;
}

constexpr int kMaxLinesPerAdvance = 100000; // bounds one call; zero-cost lines do not exist

bool isMainLabel(DedicatedLabel l) {
    return l == DedicatedLabel::PowerUp || l == DedicatedLabel::Auto || l == DedicatedLabel::Manual ||
           l == DedicatedLabel::Error;
}

constexpr DedicatedLabel kAlarmLabels[] = {DedicatedLabel::AlarmA, DedicatedLabel::AlarmB, DedicatedLabel::AlarmC};
bool printsText(const LexedLine& line) {
    if (line.entries.empty()) return false;
    const std::string& w = line.entries.front().text;
    // ERR n and ERR HIST print too (chosen: they wait for the port like P; ERR CLR prints nothing).
    const bool errPrints = w == "ERR" && !(line.entries.size() == 2 && line.entries[1].text == "CLR");
    return w == "P" || w == "PS" || w == "PA" || w == "PAS" || w == "R" || w == "RS" || w == "INPUT" || errPrints;
}
} // namespace

Microseconds Bds5Executor::costOf(const LexedLine& line) {
    // Appendix F (L7739-7774, tests/drive_core/examples/67-appendix-f-timed-commands.bds): a line takes
    // its listed time; lines the appendix does not list take 2 ms (chosen).
    if (line.entries.empty()) return 1000us; // a comment line: read like a label line (chosen)
    const std::string& w = line.entries.front().text;
    const std::size_t args = line.entries.size() - 1;
    if (w.back() == '$') return 1000us;
    if (w == "GOTO" || w == "GOSUB") return 1600us;
    if (w == "RET") return 800us;
    if (w == "TIL") return 2600us;
    if (w == "?") return 4000us;
    if (w == "P" || w == "PA" || w == "PS" || w == "PAS" || w == "R" || w == "RS")
        return args > 1 ? 3800us : 3500us; // P "X1=" X1: 3.8 ms
    if (w == "IF" || w == "ELIF" || w == "ELSE" || w == "ENDIF") return 1300us; // 9 ms for 7 lines with bodies
    if (w == "ZPE") return 1000us;
    if (w == "NORM") return 2000us;
    if (w == "MA") return args > 1 ? 5500us : 5000us; // with a velocity 5.5 ms, without 5.0 ms
    if (w == "MI") return args > 1 ? 5800us : 5000us;
    if (w == "JT" || w == "JF") return 5800us;
    if (w == "MRD") return 3500us;
    if (w == "MCA" || w == "MCI" || w == "MCD" || w == "MCGO") return 3700us; // 11.0 ms for MCI, MCI, MCGO
    if (w.size() == 2 && w[0] == 'O' && w[1] >= '1' && w[1] <= '8') return 1900us; // O1 ON
    std::string assignment; // X1=X2+1, or X1 = X2 + 1 with blanks
    for (const Entry& e : line.entries) assignment += e.text;
    const std::size_t eq = assignment.find('=');
    if (eq == std::string::npos) return 2000us;
    // X1=X2 1.7 ms; each arithmetic operator about 0.55 ms more (X1=X2+1 2.2, X1=X2*100 2.3); a logical
    // one 1.1 ms (OUT=OUT!0C8H 2.8).
    Microseconds cost = 1700us;
    for (std::size_t i = eq + 2; i < assignment.size(); ++i) {
        const char c = assignment[i];
        const char before = assignment[i - 1];
        const bool operand = std::isalnum(static_cast<unsigned char>(before)) || before == ')' || before == ']';
        if ((c == '+' || c == '-' || c == '*' || c == '/') && operand) cost += 550us;
        if ((c == '!' || c == '&') && operand) cost += 1100us;
    }
    return cost;
}

void Bds5Executor::start(std::optional<int> mainLine, Microseconds now) {
    stop();
    m_multitasking = true;
    m_cpu = now;
    m_cycleLast = m_state.variables.read("CYCLE").value_or(0) != 0;
    if (mainLine) launch(TaskLevel::Main, *mainLine);
    pollAlarms(true);
}

void Bds5Executor::stop() {
    for (Task& t : m_tasks) t = Task{};
    m_alarmLast.fill(std::nullopt);
    m_multitasking = false;
    m_errorHandling = false;
    m_paused = false;
    m_current.reset();
    m_state.pendingInput.reset();
}

void Bds5Executor::resume(Microseconds now) {
    m_paused = false;
    m_cpu = std::max(m_cpu, now);
}

void Bds5Executor::launch(TaskLevel level, int line) {
    Task& t = task(level);
    t = Task{};
    t.active = true;
    t.pc = line;
}

bool Bds5Executor::hasDedicatedTasks() const {
    const Bds5Program& p = m_state.program;
    for (const auto l :
         {DedicatedLabel::AlarmA, DedicatedLabel::AlarmB, DedicatedLabel::AlarmC, DedicatedLabel::Variable,
          DedicatedLabel::Background, DedicatedLabel::Auto, DedicatedLabel::Manual})
        if (p.dedicatedLine(l)) return true;
    return false;
}

void Bds5Executor::fireVariableTask() {
    if (!m_multitasking || task(TaskLevel::Variable).active) return; // cheap checks before the label index
    const auto line = m_state.program.dedicatedLine(DedicatedLabel::Variable);
    if (!line) return;
    if (m_state.variables.read("MULTI").value_or(1) == 0) return; // MULTI OFF holds VARIABLE$ (L4569)
    launch(TaskLevel::Variable, *line + 1);
}

// Alarms fire on the edge of their switch; at the moment multitasking is enabled, on its level (L6582).
void Bds5Executor::pollAlarms(bool atEnable) {
    for (std::size_t i = 0; i < 3; ++i) {
        const auto alarm = m_state.program.alarm(kAlarmLabels[i]);
        if (!alarm) continue;
        const auto value = m_state.variables.read(alarm->switchName);
        if (!value) continue;
        const bool inState = (*value != 0) == alarm->on;
        const bool wasInState = m_alarmLast[i].value_or(!inState);
        m_alarmLast[i] = inState;
        const bool multiOff = i == 2 && m_state.variables.read(pollRefs().multi) == 0; // C$ needs MULTI
        if (inState && (atEnable || !wasInState) && !m_tasks[i].active && !multiOff)
            launch(TaskLevel(i), alarm->line + 1);
    }
}

// AUTO$ starts on a rising CYCLE edge with MANUAL off; MANUAL$ runs, again and again, while the MANUAL
// input is on — both only when no main-level routine runs (L4960-4997; "MANUAL on" chosen, see §4.12).
void Bds5Executor::pollAutoManual() {
    const bool cycle = m_state.variables.read(pollRefs().cycle) != 0;
    const bool rising = cycle && !m_cycleLast;
    m_cycleLast = cycle;
    if (task(TaskLevel::Main).active) return;
    const bool manual = m_state.variables.read(pollRefs().manual) != 0;
    const auto label = manual ? DedicatedLabel::Manual : DedicatedLabel::Auto;
    const auto line = m_state.program.dedicatedLine(label);
    if (line && (manual || rising)) launch(TaskLevel::Main, *line + 1);
}

// RD counts down in milliseconds of the external clock: each real millisecond advances it by
// min(1, ΔPEXT / REGKHZ) (REGKHZ kHz = REGKHZ external counts a millisecond; digest §7.20). With no
// external input moving, an RD waits for good, as on a drive whose master encoder stands still.
void Bds5Executor::advanceRegulatedDwells() {
    const std::int32_t pext = m_state.variables.readUser(pollRefs().pext);
    const double khz = std::max<std::int32_t>(1, m_state.variables.readUser(pollRefs().regkhz));
    const double delta = m_pextLast ? double(pext - *m_pextLast) : 0.0;
    m_pextLast = pext;
    const double advance_ms = std::clamp(delta / khz, 0.0, 1.0);
    for (Task& t : m_tasks)
        if (t.regulatedLeft_ms) t.regulatedLeft_ms = *t.regulatedLeft_ms - advance_ms;
}

bool Bds5Executor::idle(const Task& t) const {
    if (!t.active) return true;
    if (t.waitPrinter && printerBlocked()) return true;
    if (t.waitLine && m_state.serialBusy) return true;
    if (t.waitInput && m_state.pendingInput) return true;
    if (t.waitMotion && m_state.motion.bufferFull()) return true;
    if (t.waitSegment && !m_state.motion.waitDone(*t.waitSegment)) return true;
    if (t.regulatedLeft_ms && *t.regulatedLeft_ms > 0) return true;
    if (t.wakeAt > m_cpu) return true;
    if (t.hold) {
        const auto v = m_state.variables.read(*t.hold);
        if (v && (*v != 0) != t.holdOn) return true;
    }
    return false;
}

std::optional<Microseconds> Bds5Executor::nextWake() const {
    std::optional<Microseconds> wake;
    for (const Task& t : m_tasks)
        if (t.active && t.wakeAt > m_cpu && !t.hold && (!wake || t.wakeAt < *wake)) wake = t.wakeAt;
    return wake;
}

ProgramStop Bds5Executor::advance(Microseconds now, std::string& out, std::optional<Bds5Error>& error) {
    if (!m_multitasking) return ProgramStop::Break;
    for (int n = 0; m_multitasking && !m_paused && m_cpu < now && n < kMaxLinesPerAdvance; ++n) {
        if (!m_errorHandling) {
            pollAlarms(false);
            pollAutoManual();
        }
        if (n == 0) advanceRegulatedDwells();
        // MULTI OFF disables alarm C, variable input and background (not A/B) (L4569-4577).
        const bool multi = m_state.variables.read(pollRefs().multi) != 0;
        std::optional<TaskLevel> pick;
        for (std::size_t i = 0; i < kTaskCount && !pick; ++i) {
            const auto level = TaskLevel(i);
            if (!multi &&
                (level == TaskLevel::AlarmC || level == TaskLevel::Variable || level == TaskLevel::Background))
                continue;
            if (!idle(m_tasks[i])) pick = level;
        }
        if (!pick && multi && !m_errorHandling &&
            !task(TaskLevel::Background).active) { // background restarts whenever all idle
            if (const auto line = m_state.program.dedicatedLine(DedicatedLabel::Background)) {
                launch(TaskLevel::Background, *line + 1);
                pick = TaskLevel::Background;
            }
        }
        if (!pick) {
            const auto wake = nextWake();
            m_cpu = wake && *wake < now ? *wake : now;
            continue;
        }
        m_current = pick;
        const ProgramStop stop = executeLine(*pick, out, error);
        if (stop != ProgramStop::Running) {
            this->stop(); // a break, kill or breaking error stops every task
            return stop;
        }
    }
    if (m_cpu < now && m_multitasking && !m_paused) m_cpu = now; // bounded work a call: never fall behind
    return ProgramStop::Running;
}

ProgramStop Bds5Executor::fail(Bds5Error e, std::optional<Bds5Error>& out) {
    const auto* info = catalog::bds5::findError(e.code);
    logError(m_state, e.code);
    out = std::move(e);
    // Severity 1 is a message only; 2 and above break the program (Table D.1). 53 "breaks program
    // execution" despite its level (L7295).
    if (info && info->severity <= catalog::bds5::Severity::Warning && out->code != 53) return ProgramStop::Running;
    // A breaking error runs ERROR$ if there is one, with every other task suspended (L1292, L4956-4958);
    // an error inside ERROR$ itself breaks for good.
    const auto handler = m_state.program.dedicatedLine(DedicatedLabel::Error);
    if (!handler || m_errorHandling) return ProgramStop::Error;
    for (Task& t : m_tasks) t = Task{};
    m_errorHandling = true;
    m_state.pendingInput.reset();
    launch(TaskLevel::Main, *handler);
    return ProgramStop::Running;
}

// END stops this task only; with no dedicated tasks in the program END is B (L4579-4601).
ProgramStop Bds5Executor::endTask(TaskLevel level) {
    task(level).active = false;
    if (std::exchange(m_errorHandling, false)) return ProgramStop::Running; // END in ERROR$: dormant again
    if (level == TaskLevel::Main && !hasDedicatedTasks()) return ProgramStop::Break;
    return ProgramStop::Running;
}

ProgramStop Bds5Executor::executeLine(TaskLevel level, std::string& out, std::optional<Bds5Error>& error) {
    Task& t = task(level);
    const Bds5Program& program = m_state.program;
    if (t.pc < 1 || t.pc > program.lineCount()) { // ran off the end: as END, and it costs END's time
        m_cpu += 1000us;
        return endTask(level);
    }
    const int line = t.pc;
    const LexedLine& lexed = program.lexed(line);
    if (printsText(lexed)) {
        // A printing command idles before it runs until the previous print has left (L4637), and while
        // any task's INPUT waits for the operator (L4797-4814).
        t.waitPrinter = printerBlocked();
        if (t.waitPrinter) return ProgramStop::Running;
    }
    t.waitInput = false;
    t.waitMotion = false;
    t.waitSegment.reset();
    t.regulatedLeft_ms.reset();
    const LineGate gate = m_hook ? m_hook(level, line, out) : LineGate::Run;
    t.waitLine = gate == LineGate::WaitLine;      // its trace line waits for the previous output to leave
    if (gate == LineGate::Pause) m_paused = true; // single-step: this line waits for the operator's Enter
    if (gate != LineGate::Run) return ProgramStop::Running;
    if (printsText(lexed)) m_state.serialBusy = true;
    if (m_errorHandling && !lexed.entries.empty() && lexed.entries.front().text == "EN")
        return fail(Bds5Error{55, "EN", line}, error); // NOT FROM RECOVERY (L7301)
    m_cpu += costOf(lexed);                            // lines follow one another without gaps: simulated time is exact
    ++t.pc;
    t.hold.reset();
    if (lexed.entries.empty()) {
        // An empty lexed line is a comment, or a line with quote damage: lex it again for the error.
        auto again = lexLine(program.line(line));
        if (auto* e = std::get_if<Bds5Error>(&again)) {
            e->line = line;
            return fail(*e, error);
        }
        return ProgramStop::Running;
    }
    const bool mainLevel = level == TaskLevel::Main;
    if (Bds5Program::numericLabel(lexed)) { // a label line is a 1 ms no-op at the main level
        if (mainLevel) return ProgramStop::Running;
        return fail(Bds5Error{63, lexed.entries[0].text, line}, error); // "cannot execute a label" (L5023)
    }
    if (const auto dedicated = Bds5Program::dedicatedLabel(lexed)) {
        // Main-level labels fall through; another task's code is never entered sequentially (chosen).
        if (mainLevel && isMainLabel(*dedicated)) return ProgramStop::Running;
        return endTask(level);
    }

    const Outcome o = m_interpreter.execute(lexed.entries, ExecContext{Origin::Program, line}, out);
    if (o.error) return fail(*o.error, error);
    const bool subroutinesAllowed = mainLevel; // no GOTO/GOSUB/RET in alarms, VARIABLE$, BACKGROUND$ (L4770)
    switch (o.flow) {
    case Flow::Next: return ProgramStop::Running;
    case Flow::Goto:
    case Flow::Gosub: {
        if (m_errorHandling) return fail(Bds5Error{55, lexed.entries[0].text, line}, error);
        if (!subroutinesAllowed) return fail(Bds5Error{63, lexed.entries[0].text, line}, error);
        const auto target = program.labelLine(o.target);
        if (!target) return fail(Bds5Error{70, std::to_string(o.target), line}, error);
        if (o.flow == Flow::Gosub) {
            if (int(t.gosub.size()) >= kMaxGosubLevels) return fail(Bds5Error{118, lexed.entries[0].text, line}, error);
            t.gosub.push_back(Frame{t.pc, t.ifDepth});
        }
        t.ifDepth = 0; // jumping out of IF blocks closes them (L4093-4103)
        t.pc = *target;
        return ProgramStop::Running;
    }
    case Flow::Return:
        if (!subroutinesAllowed) return fail(Bds5Error{63, "RET", line}, error);
        if (t.gosub.empty()) return fail(Bds5Error{119, "RET", line}, error);
        t.pc = t.gosub.back().returnLine;
        t.ifDepth = t.gosub.back().ifDepth;
        t.gosub.pop_back();
        return ProgramStop::Running;
    case Flow::Repeat: t.pc = line; return ProgramStop::Running;
    case Flow::Dwell: t.wakeAt = m_cpu + std::chrono::milliseconds(o.target); return ProgramStop::Running;
    case Flow::RegulatedDwell:
        for (std::size_t i = 0; i < kTaskCount; ++i) // one task at a time may use RD (ERR 62, L7326)
            if (TaskLevel(i) != level && m_tasks[i].active && m_tasks[i].regulatedLeft_ms)
                return fail(Bds5Error{62, "RD", line}, error);
        t.regulatedLeft_ms = double(o.target);
        return ProgramStop::Running;
    case Flow::WaitPrinter: // pre-execution idle of a nested print: the whole line runs again
        t.pc = line;
        t.waitPrinter = true;
        return ProgramStop::Running;
    case Flow::WaitMotion: // pre-execution idle: the line runs again when the buffer has room
        t.pc = line;
        t.waitMotion = true;
        return ProgramStop::Running;
    case Flow::WaitSegment: t.waitSegment = o.target; return ProgramStop::Running;
    case Flow::Input:
        t.waitInput = true;
        m_state.pendingInput = o.input;
        return ProgramStop::Running;
    case Flow::Hold:
        t.hold = o.text;
        t.holdOn = o.condition;
        return ProgramStop::Running;
    case Flow::If:
    case Flow::Elif: return applyIf(t, line, o, out, error);
    case Flow::Else: {
        if (t.ifDepth == 0) return fail(Bds5Error{116, "ELSE", line}, error);
        const auto end = findBlockEnd(line, true);
        if (!end) return fail(Bds5Error{115, "ELSE", line}, error);
        t.pc = *end;
        return ProgramStop::Running;
    }
    case Flow::Endif:
        if (t.ifDepth == 0) return fail(Bds5Error{116, "ENDIF", line}, error);
        --t.ifDepth;
        return ProgramStop::Running;
    case Flow::End: return endTask(level);
    case Flow::Break: return ProgramStop::Break;
    case Flow::Kill: return ProgramStop::Kill;
    case Flow::Stop: return ProgramStop::Running; // S in a program stops motion only (motion: issue 4)
    case Flow::Run: {                             // v3: RUN inside a program restarts at the label (L9307)
        const auto target = o.target < 0 ? std::optional<int>() : program.labelLine(o.target);
        if (o.target >= 0 && !target) return fail(Bds5Error{70, std::to_string(o.target), line}, error);
        start(target, m_cpu);
        return ProgramStop::Running;
    }
    case Flow::Load:
    case Flow::List:
    case Flow::Edit: return fail(Bds5Error{53, lexed.entries[0].text, line}, error);
    }
    return ProgramStop::Running;
}

ProgramStop Bds5Executor::applyIf(Task& t, int line, const Outcome& o, std::string& out,
                                  std::optional<Bds5Error>& error) {
    const Bds5Program& program = m_state.program;
    if (o.flow == Flow::Elif) { // reached in sequence: the block before it ran, skip to ENDIF
        if (t.ifDepth == 0) return fail(Bds5Error{116, "ELIF", line}, error);
        const auto end = findBlockEnd(line, true);
        if (!end) return fail(Bds5Error{115, "ELIF", line}, error);
        t.pc = *end;
        return ProgramStop::Running;
    }
    ++t.ifDepth;
    int at = line;
    bool taken = o.condition;
    while (!taken) { // try the ELIFs in turn, then the ELSE; every condition costs its line's time
        const auto next = findBlockEnd(at, false);
        if (!next) return fail(Bds5Error{115, "IF", line}, error);
        const LexedLine& l = program.lexed(*next);
        at = *next;
        if (l.entries.front().text == "ELIF") {
            m_cpu += costOf(l);
            const Outcome c = m_interpreter.execute(l.entries, ExecContext{Origin::Program, at}, out);
            if (c.error) return fail(*c.error, error);
            taken = c.condition;
        } else if (l.entries.front().text == "ENDIF") {
            t.pc = at; // execute the ENDIF line itself (it shows in a trace)
            return ProgramStop::Running;
        } else {
            taken = true; // ELSE runs its block
        }
    }
    t.pc = at + 1;
    return ProgramStop::Running;
}

std::optional<int> Bds5Executor::findBlockEnd(int from, bool toEndif) const {
    const Bds5Program& program = m_state.program;
    int depth = 0;
    for (int l = from + 1; l <= program.lineCount(); ++l) {
        const LexedLine& lexed = program.lexed(l);
        if (lexed.entries.empty()) continue;
        const std::string& w = lexed.entries.front().text;
        if (w == "IF")
            ++depth;
        else if (w == "ENDIF") {
            if (depth == 0) return l;
            --depth;
        } else if (depth == 0 && !toEndif && (w == "ELIF" || w == "ELSE"))
            return l;
    }
    return std::nullopt;
}

} // namespace drive_core::bds5
