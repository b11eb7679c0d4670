// The ServoBASIC Plus VM: program state, waits, interrupts, breakpoints and the instruction loop.
#include "sc750_vm.h"

#include <cmath>

namespace drive_core::sc750 {

void Vm::load(Program program) {
    m_program = std::move(program);
    m_statementStart.assign(m_program->code.size() + 1, false);
    for (const LineEntry& l : m_program->lines)
        if (l.address >= 0 && std::size_t(l.address) < m_statementStart.size())
            m_statementStart[std::size_t(l.address)] = true;
    m_breakpoints.clear();
    m_vars.clear();
    clearVariables(false);
    reset();
}

void Vm::unload() {
    m_program.reset();
    m_vars.clear();
    m_breakpoints.clear();
    m_state = State::NoProgram;
}

void Vm::reset() {
    if (!m_program) return;
    m_pc = 0;
    m_stack.clear();
    m_gosub.clear();
    m_interrupt.reset();
    m_wait = Wait::None;
    m_column = 0;
    m_error.clear();
    m_skipBreakpointAt = -1;
    m_state = State::Loaded;
}

void Vm::powerCycle() {
    if (!m_program) return;
    reset();
    clearVariables(true);
}

void Vm::start() {
    if (!m_program) return;
    reset();
    clearVariables(true);
    m_state = State::Running;
}

void Vm::stop() {
    if (m_state == State::Running) m_state = State::Stopped;
}

void Vm::resume() {
    if (m_state != State::Stopped && m_state != State::AtBreakpoint) return;
    m_skipBreakpointAt = m_pc;
    m_state = State::Running;
}

void Vm::clearVariables(bool keepNonVolatile) {
    const auto& vars = m_program->variables;
    m_vars.resize(vars.size());
    for (std::size_t i = 0; i < vars.size(); ++i) {
        if (keepNonVolatile && vars[i].nonVolatile && !m_vars[i].empty()) continue;
        const Value zero = vars[i].type == ValueType::String  ? Value(std::string())
                           : vars[i].type == ValueType::Float ? Value(0.0f)
                                                              : Value(std::int32_t(0));
        m_vars[i].assign(std::size_t(vars[i].count), zero);
    }
}

bool Vm::addBreakpoint(int line) {
    if (!m_program) return false;
    const std::int32_t address = m_program->addressOfLine(line);
    if (address < 0) return false;
    if (m_breakpoints.count(address) == 0 && m_breakpoints.size() >= 10) return false;
    m_breakpoints.insert(address);
    return true;
}

bool Vm::removeBreakpoint(int line) {
    if (!m_program) return false;
    return m_breakpoints.erase(m_program->addressOfLine(line)) != 0;
}

void Vm::clearBreakpoints() {
    m_breakpoints.clear();
}

std::vector<int> Vm::breakpointLines() const {
    std::vector<int> lines;
    for (std::int32_t a : m_breakpoints) lines.push_back(m_program->lineAt(a));
    return lines;
}

void Vm::updateAttention() {
    m_attention = !m_breakpoints.empty() || m_host.anyInterruptEnabled();
}

void Vm::tick(std::int64_t tickCount, int budget) {
    m_tick = tickCount;
    if (m_state != State::Running) return;
    updateAttention();
    if (m_wait != Wait::None) {
        if (!m_interrupt && m_host.anyInterruptEnabled()) {
            const int source = m_host.takeInterrupt();
            if (source >= 0 && m_program->interrupts[std::size_t(source)] >= 0) enterInterrupt(source);
        }
        if (m_wait != Wait::None && !resolveWait(tickCount)) return;
    }
    // A loop that only reads (WHILE MOVING : WEND, the manual's idiom) repeats the same pass until the tick
    // ends: nothing it reads changes within a tick (the drive's state moves between ticks) and it changes
    // nothing. The pass is anchored at the first line start or loop head the program reaches after the
    // tick's start or its last write (there the expression stack holds nothing a pass will use: a tick may
    // end mid-expression). Back at the anchor with the same stack and nothing written, every further pass
    // would do the same: the budget's whole passes are skipped and only the remainder runs, so the program
    // ends the tick at exactly the instruction it would have reached.
    const auto& code = m_program->code;
    int anchor = -1; // -1: none yet
    int anchorBudget = 0;
    std::size_t anchorStack = 0;
    std::int64_t anchorInterrupts = 0;
    bool jumpedBack = false;
    while (budget > 0 && m_state == State::Running && m_wait == Wait::None) {
        if (m_attention && !attend()) return;
        if (m_pc < 0 || std::size_t(m_pc) >= code.size()) {
            m_state = State::Ended;
            return;
        }
        if (jumpedBack || m_statementStart[std::size_t(m_pc)]) {
            if (m_pc == anchor && m_stack.size() == anchorStack && m_interruptsEntered == anchorInterrupts) {
                budget %= anchorBudget - budget; // a pass took that many: whole passes change nothing
                anchor = -2;                     // none again this tick: the remainder is shorter than a pass
                if (budget == 0) break;
            } else if (anchor == -1) {
                anchor = m_pc;
                anchorBudget = budget;
                anchorStack = m_stack.size();
                anchorInterrupts = m_interruptsEntered;
            }
        }
        --budget;
        const int at = m_pc++;
        const Instruction& ins = code[std::size_t(at)];
        execute(ins);
        jumpedBack = (ins.op == Op::Jump || ins.op == Op::JumpIfZero) && m_pc <= at;
        if (!readsOnly(ins.op)) anchor = -1;
    }
}

bool Vm::readsOnly(Op op) {
    switch (op) {
    case Op::Nop: case Op::PushI: case Op::PushF: case Op::PushS: case Op::LoadV: case Op::LoadA: case Op::LoadP:
    case Op::IntToFloat: case Op::FloatToInt: case Op::AddI: case Op::SubI: case Op::MulI: case Op::ModI:
    case Op::NegI: case Op::AddF: case Op::SubF: case Op::MulF: case Op::DivF: case Op::PowF: case Op::NegF:
    case Op::Concat: case Op::CompareI: case Op::CompareF: case Op::CompareS: case Op::And: case Op::Or:
    case Op::Xor: case Op::Not: case Op::Jump: case Op::JumpIfZero:
        return true;
    default: return false; // writes, calls (RND, INKEY$ ...), I/O, motion, GOSUB/RETURN, FOR's counter
    }
}

bool Vm::attend() {
    if (!m_statementStart[std::size_t(m_pc)]) return true;
    if (m_breakpoints.count(m_pc) != 0 && m_skipBreakpointAt != m_pc) {
        m_state = State::AtBreakpoint;
        return false;
    }
    m_skipBreakpointAt = -1;
    if (!m_interrupt && m_host.anyInterruptEnabled()) {
        const int source = m_host.takeInterrupt();
        if (source >= 0 && m_program->interrupts[std::size_t(source)] >= 0) enterInterrupt(source);
    }
    return true;
}

void Vm::enterInterrupt(int source) {
    ++m_interruptsEntered;
    m_interrupt = Frame{m_pc, m_wait, m_pauseUntil, m_stack.size(), m_gosub.size()};
    m_wait = Wait::None;
    m_pc = m_program->interrupts[std::size_t(source)];
}

bool Vm::resolveWait(std::int64_t tickCount) {
    switch (m_wait) {
    case Wait::None: return true;
    case Wait::Pause:
        if (tickCount < m_pauseUntil) return false;
        break;
    case Wait::When: {
        const double x = m_host.whenSample(m_whenSource);
        const bool met = m_whenRelation == 0   ? x == m_whenValue
                         : m_whenRelation == 1 ? x > m_whenValue
                                               : x < m_whenValue;
        if (!met) return false;
        m_host.whenLatch();
        m_host.whenAction(m_whenAction, m_whenArg, m_whenActionValue);
        break;
    }
    case Wait::Output:
        if (m_host.outputBacklog() > VmHost::kTransmitBuffer) return false;
        break;
    case Wait::Input: {
        const auto line = m_host.takeLine();
        if (!line) return false;
        if (m_inputType == ValueType::String) {
            std::string text = *line;
            while (!text.empty() && text.front() == ' ') text.erase(0, 1);
            while (!text.empty() && text.back() == ' ') text.pop_back();
            if (text.size() > std::size_t(kMaxStringLength)) text.resize(std::size_t(kMaxStringLength));
            m_stack.push_back(text);
        } else {
            const auto v = parseValue(line->empty() ? "0" : *line, m_inputType);
            if (!v) {
                print("?Redo from start\r\n");
                printPrompt();
                return false;
            }
            m_stack.push_back(*v);
        }
        break;
    }
    }
    m_wait = Wait::None;
    return true;
}

void Vm::runtimeError(const std::string& message) {
    if (m_pc > 0) --m_pc; // report (and stay at) the instruction that failed
    m_error = message + " (line " + std::to_string(currentLine()) + ")";
    m_state = State::Error;
}

Value Vm::pop() {
    if (m_stack.empty()) { // only a damaged .BIN gets here: the compiler balances the stack
        runtimeError("BAD PROGRAM (STACK)");
        return std::int32_t(0);
    }
    Value v = std::move(m_stack.back());
    m_stack.pop_back();
    return v;
}

std::string Vm::popString() {
    Value v = pop();
    if (auto* s = std::get_if<std::string>(&v)) return std::move(*s);
    runtimeError("BAD PROGRAM (TYPE)");
    return {};
}

std::int32_t Vm::popInt() {
    if (!m_stack.empty()) // the common case, without moving the value out (a condition, an index)
        if (const auto* i = std::get_if<std::int32_t>(&m_stack.back())) {
            const std::int32_t v = *i;
            m_stack.pop_back();
            return v;
        }
    const Value v = pop();
    if (const auto* i = std::get_if<std::int32_t>(&v)) return *i;
    return toInteger(toDouble(v)).value_or(0);
}

float Vm::popFloat() {
    return float(toDouble(pop()));
}

void Vm::pushInt(std::int64_t v) {
    if (v > 2147483647LL || v < -2147483648LL) return runtimeError("OVERFLOW");
    m_stack.emplace_back(std::in_place_type<std::int32_t>, std::int32_t(v));
}

void Vm::print(const std::string& text) {
    for (char c : text) m_column = c == '\n' || c == '\r' ? 0 : m_column + 1;
    m_host.write(text);
    if (m_wait == Wait::None && m_host.outputBacklog() > VmHost::kTransmitBuffer) m_wait = Wait::Output;
}

void Vm::printPrompt() {
    print(m_prompt + (m_promptQuestion ? "? " : ""));
}

} // namespace drive_core::sc750
