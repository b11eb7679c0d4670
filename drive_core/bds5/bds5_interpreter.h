// Executes one BDS5 instruction (a span of lexed entries) against the drive's state. It never parses
// characters (the lexer and expression evaluator do), never touches the UART (the drive frames output)
// and never moves a program counter: control flow comes back as an Outcome for the executor to apply.
#pragma once

#include "bds5_error.h"
#include "bds5_lexer.h"
#include "bds5_motion.h"
#include "bds5_program.h"
#include "bds5_recorder.h"
#include "bds5_servo.h"
#include "bds5_variable_store.h"

#include <deque>
#include <optional>
#include <span>
#include <string>

namespace drive_core::bds5 {

// INPUT "text" VAR[d] [min max] (L4380-4436): what the drive waits for.
struct InputRequest {
    std::string variable;     // "X2"
    int decimals = 0;         // the typed value is multiplied by 10^decimals
    std::int64_t minimum = 0; // limits after scaling, already clipped to the variable's own limits
    std::int64_t maximum = 0;
    std::string text; // the prompt text as printed (control characters expanded)
};

// State the interpreter reads and changes; owned by Bds5Drive.
struct Bds5State {
    Bds5VariableStore variables;
    Bds5Program program;
    Bds5Motion motion;
    Bds5Servo servo; // the loops and the simulated motor (PFB, VFB, PE, ICMD come from here)
    std::string motorName = "REF-MEDIUM"; // the reference motor on the bench (physics::referenceMotors)
    Bds5Recorder recorder;
    std::uint32_t randomState = 1; // RAND's generator (v3 L9310)
    // v3 real-time trace (TRECORD/TPLAY, L9317-9319): the last lines executed, oldest first.
    struct TraceEntry {
        int line;
        std::string prefix; // the task's trace prefix, "t..", "tA." ...
        std::string text;
    };
    std::deque<TraceEntry> traceBuffer;
    bool traceRecording = false;
    std::deque<int> errorHistory;             // ERR HIST, newest first, at most 20 entries (L6110-6148)
    bool enabled = false;                     // drive enabled (EN) / inhibited (DIS, K)
    bool serialBusy = false;                  // the UART is still sending: printing commands idle before running
    std::optional<InputRequest> pendingInput; // an INPUT waits: every print idles (L4797-4814)
};

constexpr std::size_t kErrorHistorySize = 20;

// Appends an error number to the history (newest first, 20 entries).
void logError(Bds5State& state, int code);

// EXTDX has just changed (v3, L9295-9297, L9309): X251-X750 appear or disappear. They live in the memory of
// the RECORD (PC-SCOPE) and real-time trace buffers, which cannot be used while EXTDX is on, so either change
// discards the recording and the trace, and the extended registers start from 0 (DECISIONS.md 12).
void switchExtendedRegisters(Bds5State& state);

// Where an instruction comes from; decides which commands are legal (App. C "Modes").
enum class Origin { Terminal, Monitor, Program };

struct ExecContext {
    Origin origin = Origin::Terminal;
    int line = 0;        // program line number (Origin::Program)
    bool nested = false; // the instruction of a ? or TIL (the executor checked the line's own first word)
};

// What the instruction asks of whoever runs it.
enum class Flow {
    Next,           // go on with the next line
    Goto,           // target = label line's label
    Gosub,          // target = label
    Return,         // RET
    End,            // END: this task ends
    Break,          // B: all tasks stop, back to interactive
    Kill,           // K: disable and break
    Stop,           // S: stop motion (and, from monitor, break)
    Repeat,         // TIL not yet satisfied: run this line again
    Dwell,          // D: idle for target milliseconds
    RegulatedDwell, // RD: idle for target milliseconds of the external input's clock
    Hold,           // H: idle until switch `text` is ON (condition true) or OFF
    Run,            // RUN [label]: target = label, or -1 for "enable multitasking only"
    Load,           // >BDS [password]: text = password
    List,           // <BDS
    Edit,           // ED: enter the resident editor
    Input,          // INPUT: the program waits for the operator (Outcome::input)
    WaitMotion,     // MA/MI/MCGO with the motion buffer full: run this line again when there is room
    WaitPrinter,    // a print inside ? or TIL while the port is busy: run this line again when it is free
    WaitSegment,    // W n: idle until segment target of the last motion command has started
    If,             // IF c: condition
    Elif,           // ELIF c: condition
    Else,
    Endif,
};

struct Outcome {
    std::optional<Bds5Error> error;
    Flow flow = Flow::Next;
    int target = 0;
    bool condition = false;
    std::string text;
    std::optional<InputRequest> input;
};

class Bds5Interpreter {
public:
    explicit Bds5Interpreter(Bds5State& state) : m_state(state) {}

    // Runs one instruction. Printed text (with its CR LF line ends) is appended to out.
    Outcome execute(std::span<const Entry> entries, const ExecContext& context, std::string& out);

private:
    Outcome dispatch(std::span<const Entry> entries, const ExecContext& context, std::string& out);
    Outcome quickIf(std::span<const Entry> entries, const ExecContext& context, std::string& out);
    Outcome til(std::span<const Entry> entries, const ExecContext& context, std::string& out);
    Outcome jump(Flow flow, std::span<const Entry> entries);
    std::optional<Bds5Error> print(std::span<const Entry> entries, std::string_view terminator, bool status,
                                   std::string& out);
    Outcome input(std::span<const Entry> entries, std::string& out);
    std::string statusWord() const;
    std::optional<Bds5Error> assign(std::span<const Entry> entries);
    std::optional<Bds5Error> errCommand(std::span<const Entry> entries, std::string& out);
    Outcome dump(std::span<const Entry> entries, std::string& out);
    // cond := expr ('GT'|'GE'|'LT'|'LE'|'EQ'|'NE') expr — three entries starting at entries[0].
    std::optional<bool> condition(std::span<const Entry> entries, std::optional<Bds5Error>& error) const;
    std::optional<std::int32_t> readValue(std::string_view name) const;
    Outcome motionCommand(std::span<const Entry> entries, const ExecContext& context);
    Outcome record(std::span<const Entry> entries, std::string& out);
    Outcome tune(std::span<const Entry> entries);
    Outcome random(std::span<const Entry> entries);
    Outcome realTimeTrace(std::span<const Entry> entries, std::string& out);
    // Evaluates an entry and converts it from user to basic units; error set on failure.
    std::optional<std::int64_t> basicValue(const Entry& entry, catalog::bds5::UnitClass unit,
                                           std::optional<Bds5Error>& error) const;

    Bds5State& m_state;
};

} // namespace drive_core::bds5
