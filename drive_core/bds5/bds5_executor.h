// Runs the user program: the main task's program counter, GOSUB stack, IF nesting, dwell, and the time
// each line costs (App. F). The interpreter executes each instruction; the executor applies its Flow.
#pragma once

#include "bds5_interpreter.h"

#include "drive_core/drive.h"

#include <optional>
#include <string>
#include <vector>

namespace drive_core::bds5 {

constexpr int kMaxGosubLevels = 4; // ERR 118 on the fifth (L3791-3821)

// Why the program stopped.
enum class ProgramStop {
    Running, // still going (or idle in a dwell)
    Break,   // B, END with no other task, end of program: back to interactive
    Error,   // a breaking error (severity >= 2): message printed, back to interactive
    Kill,    // K: drive disabled, back to interactive
};

class Bds5Executor {
public:
    Bds5Executor(Bds5State& state, Bds5Interpreter& interpreter) : m_state(state), m_interpreter(interpreter) {}

    // Starts the main task at a program line (the label line itself runs first, costing its 1 ms).
    void start(int line, Microseconds now);
    void stop() { m_running = false; }
    bool running() const { return m_running; }

    // Executes every line whose time has come by `now`. Output goes to out; a breaking error is returned
    // through error (already logged). Returns whether the program still runs.
    ProgramStop advance(Microseconds now, std::string& out, std::optional<Bds5Error>& error);

    // Cost of one line in microseconds (App. F, L7723-7775; 2 ms where the appendix is silent — chosen).
    static Microseconds costOf(const LexedLine& line);

private:
    struct Frame {
        int returnLine;
        int ifDepth;
    };

    ProgramStop executeLine(std::string& out, std::optional<Bds5Error>& error);
    ProgramStop fail(Bds5Error error, std::optional<Bds5Error>& out);
    // From an IF/ELIF line, the next ELIF/ELSE/ENDIF of the same block (or its ENDIF when toEndif).
    std::optional<int> findBlockEnd(int from, bool toEndif) const;

    Bds5State& m_state;
    Bds5Interpreter& m_interpreter;
    bool m_running = false;
    int m_pc = 0;                 // next line to execute
    Microseconds m_busyUntil{0};  // the line being executed finishes then
    std::vector<Frame> m_gosub;
    int m_ifDepth = 0;
};

} // namespace drive_core::bds5
