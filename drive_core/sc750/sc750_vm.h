// The ServoBASIC Plus virtual machine: runs a compiled Program's stack code in 0.427 ms ticks with
// injected time. Blocking statements (PAUSE, WHEN, INPUT) wait across ticks; interrupts are taken
// between statements and while waiting; breakpoints, stop and continue for the debugger. Never parses.
// Debugging and interrupts cost one flag check per instruction when off.
#pragma once

#include "sc750_program.h"
#include "sc750_value.h"
#include "sc750_vm_host.h"

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace drive_core::sc750 {

inline constexpr double kTick_s = 0.000427; // WHEN polling period (L1972), also the TIME tick (L2048)

class Vm {
public:
    enum class State { NoProgram, Loaded, Running, Stopped, AtBreakpoint, Ended, Error };
    enum class Wait { None, Pause, When, Input, Output };

    explicit Vm(VmHost& host) : m_host(host) {}

    void load(Program program); // State Loaded; all variables cleared
    void unload();
    // Run from the top (Run Program): volatile variables cleared, NV user variables kept.
    void start();
    void stop();       // Ctrl C: suspends where it is
    void resume();     // Continue: after a stop or a breakpoint
    void reset();      // back to Loaded, nothing running
    void powerCycle(); // reset, and volatile user variables cleared (NV ones kept, L996-L1001)

    // One tick: resolves the wait in progress, takes an interrupt, then runs up to budget instructions.
    void tick(std::int64_t tickCount, int budget);

    // Breakpoints by source line (at most 10, L2710); false when the line has no statement or too many.
    bool addBreakpoint(int line);
    bool removeBreakpoint(int line);
    void clearBreakpoints();
    std::vector<int> breakpointLines() const;

    State state() const { return m_state; }
    int pc() const { return m_pc; } // the next instruction
    std::size_t stackDepth() const { return m_stack.size(); }
    Wait wait() const { return m_wait; }
    bool running() const { return m_state == State::Running; }
    int currentLine() const { return m_program ? m_program->lineAt(m_pc) : 0; }
    const std::string& errorText() const { return m_error; }
    const Program* program() const { return m_program ? &*m_program : nullptr; }

    // User variables for the Variables window: index into program()->variables, element for arrays.
    int findVariable(const std::string& upperName) const;
    std::optional<Value> variable(int index, int element) const;
    bool setVariable(int index, int element, const Value& value);

private:
    struct Frame { // an interrupt in progress: where and how the interrupted code was waiting
        std::int32_t pc = 0;
        Wait wait = Wait::None;
        std::int64_t pauseUntil = 0;
        std::size_t stackSize = 0;
        std::size_t gosubDepth = 0;
    };

    void execute(const Instruction& ins);
    bool attend(); // breakpoints and interrupts at a statement boundary; false: stop running this tick
    bool resolveWait(std::int64_t tickCount);
    void enterInterrupt(int source);
    // The instruction only reads (variables, the drive's values, constants) and computes or jumps.
    static bool readsOnly(Op op);
    void runtimeError(const std::string& message);
    void clearVariables(bool keepNonVolatile);
    void updateAttention();
    Value pop();
    std::int32_t popInt();
    std::string popString();
    float popFloat();
    void pushInt(std::int64_t v);
    void print(const std::string& text);
    void printPrompt();
    Value callFunction(int index, int argc);

    VmHost& m_host;
    std::optional<Program> m_program;
    std::vector<std::vector<Value>> m_vars;
    std::vector<bool> m_statementStart;
    std::vector<Value> m_stack;
    std::vector<std::int32_t> m_gosub;
    std::optional<Frame> m_interrupt;
    std::set<std::int32_t> m_breakpoints; // addresses
    std::int32_t m_pc = 0;
    std::int32_t m_skipBreakpointAt = -1; // continuing from a breakpoint must not stop there again
    State m_state = State::NoProgram;
    Wait m_wait = Wait::None;
    std::int64_t m_tick = 0;
    std::int64_t m_interruptsEntered = 0; // a pass of a loop that took an interrupt is not a repeat
    std::int64_t m_pauseUntil = 0;
    // WHEN in progress
    int m_whenSource = 0, m_whenRelation = 0, m_whenAction = 0, m_whenArg = 0;
    float m_whenValue = 0, m_whenActionValue = 0;
    // INPUT in progress
    ValueType m_inputType = ValueType::Integer;
    std::string m_prompt;
    bool m_promptQuestion = true;
    int m_column = 0; // output column, for `,` zones
    bool m_attention = false;
    std::string m_error;
    std::int32_t m_lanInt[33] = {};
    float m_lanFloat[33] = {};
};

} // namespace drive_core::sc750
