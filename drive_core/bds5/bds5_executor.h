// Runs the user program's tasks (Table 4.5): alarms A/B/C, VARIABLE$, the main level (POWER-UP$,
// AUTO$, MANUAL$, n$, ERROR$) and BACKGROUND$, on one simulated processor. Each line costs its App. F
// time; the highest-priority task that is not idling runs. The interpreter executes each instruction;
// the executor applies the Flow it returns.
#pragma once

#include "bds5_interpreter.h"

#include "drive_core/drive.h"

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace drive_core::bds5 {

constexpr int kMaxGosubLevels = 4; // ERR 118 on the fifth (L3791-3821)

// Task levels, highest priority first (Table 4.5, L4603-4615).
enum class TaskLevel { AlarmA, AlarmB, AlarmC, Variable, Main, Background };
constexpr std::size_t kTaskCount = 6;

// Why the program stopped.
enum class ProgramStop {
    Running, // multitasking still enabled (a task runs, idles, or the drive is dormant)
    Break,   // B, END with no other task, end of program: back to interactive
    Error,   // a breaking error (severity >= 2): message printed, back to interactive
    Kill,    // K: drive disabled, back to interactive
};

class Bds5Executor {
public:
    Bds5Executor(Bds5State& state, Bds5Interpreter& interpreter) : m_state(state), m_interpreter(interpreter) {}

    // RUN [label]: enables multitasking and, with a line, starts the main task there (the label line
    // itself runs first, costing its 1 ms). Alarms whose switch is already in state fire at once (L6582).
    void start(std::optional<int> mainLine, Microseconds now);
    // B / ^X / power-down: every task stops, multitasking is disabled.
    void stop();
    bool running() const { return m_multitasking; }
    // ^V: fires VARIABLE$ if the program has one and multitasking allows it (L4818).
    void fireVariableTask();
    // The level whose line runs next (for task prompts in single-step and trace, Table 5.1).
    std::optional<TaskLevel> currentTask() const { return m_current; }

    // What the line hook lets the line about to run do.
    enum class LineGate {
        Run,      // the line runs (its trace line, if any, is already in out)
        Pause,    // single-step: the program waits before this line until resume()
        WaitLine, // trace: the line idles until the serial line is free, then asks again (L4637)
    };
    // Called before each line runs, with the output buffer (for trace lines in order with prints).
    using LineHook = std::function<LineGate(TaskLevel level, int line, std::string& out)>;
    void setLineHook(LineHook hook) { m_hook = std::move(hook); }
    bool paused() const { return m_paused; }
    // Continues after a pause; the processor does not catch up the time it spent paused.
    void resume(Microseconds now);

    // Executes every line whose time has come by `now`. Output goes to out; an error is returned through
    // error (already logged; a warning leaves the program running).
    ProgramStop advance(Microseconds now, std::string& out, std::optional<Bds5Error>& error);

    // Cost of one line in microseconds (App. F, L7723-7775; 2 ms where the appendix is silent — chosen).
    static Microseconds costOf(const LexedLine& line);

private:
    struct Frame {
        int returnLine;
        int ifDepth;
    };
    struct Task {
        bool active = false;
        int pc = 0;
        std::vector<Frame> gosub;
        int ifDepth = 0;
        Microseconds wakeAt{0};                 // D: idle until then
        std::optional<std::string> hold;        // H: idle until this switch ...
        bool holdOn = true;                     // ... is in this state
        bool waitPrinter = false;               // a print waits for the serial port (pre-execution idle)
        bool waitLine = false;                  // a traced line waits for the serial line (not for INPUT)
        bool waitInput = false;                 // INPUT: idle until the operator answers
        bool waitMotion = false;                // a move waits for room in the motion buffer
        std::optional<int> waitSegment;         // W n
        std::optional<double> regulatedLeft_ms; // RD: external-clock milliseconds still to go
    };

    Task& task(TaskLevel level) { return m_tasks[std::size_t(level)]; }
    void launch(TaskLevel level, int line);
    void pollAlarms(bool atEnable);
    void pollAutoManual();
    void advanceRegulatedDwells();
    bool idle(const Task& t) const;
    bool hasDedicatedTasks() const;
    std::optional<Microseconds> nextWake() const;
    ProgramStop executeLine(TaskLevel level, std::string& out, std::optional<Bds5Error>& error);
    ProgramStop endTask(TaskLevel level);
    ProgramStop fail(Bds5Error error, std::optional<Bds5Error>& out);
    bool printerBlocked() const { return m_state.serialBusy || m_state.pendingInput.has_value(); }
    ProgramStop applyIf(Task& t, int line, const Outcome& o, std::string& out, std::optional<Bds5Error>& error);
    // From an IF/ELIF line, the next ELIF/ELSE/ENDIF of the same block (or its ENDIF when toEndif).
    std::optional<int> findBlockEnd(int from, bool toEndif) const;

    Bds5State& m_state;
    Bds5Interpreter& m_interpreter;
    std::array<Task, kTaskCount> m_tasks;
    std::array<std::optional<bool>, 3> m_alarmLast; // last sampled state of each alarm's switch
    bool m_cycleLast = false;                       // the CYCLE input, for AUTO$'s rising edge
    std::optional<std::int32_t> m_pextLast;         // PEXT at the last regulated-dwell update
    bool m_multitasking = false;
    bool m_errorHandling = false; // ERROR$ runs: every other task is suspended (L4956-4958)
    bool m_paused = false;
    LineHook m_hook;
    Microseconds m_cpu{0}; // the processor has executed everything up to this time
    std::optional<TaskLevel> m_current;
};

} // namespace drive_core::bds5
