// The MPL interpreter: a character-stream state machine, not a line interpreter (digest §9.1). Characters
// from the SCI or from the program buffer go through the same machine; commands act on <cr>, on display
// characters and on mid-line triggers (+ - * , ; ^), so J,-*+*- and I,+,- behave as documented. It blocks
// only on waits (, ; D U C^ single-step), which the drive polls as time passes. Parsing: this file and
// pmc960_interpreter.cpp; command actions: pmc960_commands.cpp; displays: pmc960_displays.cpp.
#pragma once

#include "pmc960_state.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace drive_core::pmc960 {

// What the interpreter asks of the controller around it (the drive). All calls come from within feed(),
// run() or poll().
class Pmc960Sink {
public:
    virtual ~Pmc960Sink() = default;
    virtual void send(std::string_view bytes) = 0;               // echo, displays, the } handshake of a sync
    virtual void raise(int code) = 0;                            // #xx; the drive aborts the interpreter and prompts
    virtual void commandDone() = 0;                              // back at command level: the drive sends the prompt
    virtual void enterEditor(std::size_t cursor) = 0;            // P{ P<cr> P<label>
    virtual void listProgram(bool lineByLine) = 0;               // P? P!
    virtual void stream(std::string command, int period_ms) = 0; // <cmd>%[<time>]<cr>
    virtual void softwareReset() = 0;                            // N*
    virtual void autobaud() = 0;                                 // N<cr>
};

enum class Pmc960Wait { None, MotionDone, ConstantSpeed, Dwell, Until, SingleStep, ContourReady, CamSegment };

class Pmc960Interpreter {
public:
    Pmc960Interpreter(Pmc960State& state, Pmc960Sink& sink) : m_state(state), m_sink(sink) {}

    // A character typed at the SCI (echoed per THC bit 0; the terminating <cr> is not echoed).
    void feed(char c);
    // Executes up to budget characters of the running program; returns how many it used.
    int run(int budget);
    // Time has passed: checks the wait. now is the controller's clock.
    void poll(std::int64_t now_us);
    // Single-step: the @ from the SCI that lets the program pass a label (THC bit 2).
    void grantStep();
    // A <cr> while R waits to accept the next segment leaves the contour command without error (L2227).
    void contourReturn();
    // ESC: ends what is going on. Returns the error code the manual gives for that context, 0 for none.
    int escape();
    // After an error, a break or a reset: no program, no wait, back at command level. The rest of an SCI
    // line an error interrupted is read as new commands (a character stream has no lines to drop).
    void abort();
    // Runs the program from label (START'+ADDR, EXEC', TLP). false: no such label.
    bool start(char label);

    bool running() const { return m_running; }
    Pmc960Wait wait() const { return m_wait; }
    bool idle() const { return !m_running && m_wait == Pmc960Wait::None && m_phase == Phase::Idle; }
    // Inside a NUL-prefixed binary number: the next byte is data whatever its value (only 1DH is doubled).
    bool readingBinaryNumber() const { return m_binaryBytes > 0; }
    // The command being read, upper case ("B", "TGP"; empty at command level), and the label a B, F or L
    // has read (0 until then). For the program checker (pmc960_checker.cpp), which reads through this machine.
    const std::string& command() const { return m_command; }
    char label() const { return m_label; }

    // The text a display character produces for command (upper case: "V", "SF", "TG", "SB"), kind one of
    // ? ! &. Empty if the command has no such display. Used for polls and % streams too.
    std::string display(std::string_view command, char kind) const;

private:
    enum class Phase { Idle, Letters, Arguments, Label, SkipLine, Stream };
    enum class Source { Sci, Program };

    void dispatch(char c);
    void letter(char c);
    void argument(char c);
    bool displayChar(char c);
    bool collectDigit(char c, bool hexAlways);
    int binaryWidth() const;
    void finish();
    void resetCommand();
    void fail(int code);
    void beginWait(Pmc960Wait wait, bool endsCommand);
    bool waitSatisfied() const;
    void endProgram();
    bool jump(char label);
    void labelPassed(char label);

    // Command families (pmc960_commands.cpp).
    void motionArgument(char c, bool first);
    void conditionArgument(char c);
    void loopArgument(char c);
    void valueArgument(char c, bool first);
    void gainsArgument(char c);
    void programArgument(char c);
    void camArgument(char c, bool first);
    void contourArgument(char c);
    void stopMotion();
    bool startMotion(char command, int sign);
    bool motionAllowed(bool reverse);
    bool applyValue(const std::string& command, std::int64_t value);
    bool writable();
    bool conditionHolds() const;

    std::int64_t number() const;
    bool numberGiven() const { return !m_digits.empty() || m_binaryGiven; }
    void clearNumber();

    Pmc960State& m_state;
    Pmc960Sink& m_sink;
    Source m_source = Source::Sci;
    Phase m_phase = Phase::Idle;
    std::string m_command; // upper case: "A", "SM", "TGP", "B"
    std::string m_digits;
    std::string m_fraction; // after ':' (fixed point, masks, cam speed)
    bool m_colon = false;
    bool m_binaryGiven = false;
    bool m_hexNumber = false;
    bool m_promptAtCr = false; // an @ comment line typed at the SCI: prompt at its <cr>
    char m_lastChar = 0;
    int m_contourTick = 0;   // R: the tick character being read, 0 = expecting a tick
    int m_contourDigits = 0; // R: hex digits the count takes
    std::int64_t m_binary = 0;
    int m_binaryBytes = 0; // still to read of a NUL-prefixed binary number
    int m_sign = 0;        // prefix sign (C) or postfix sign (OA, SL)
    char m_label = 0;
    char m_counter = 0;       // X Y Z, 0 = default
    bool m_triggered = false; // a motion trigger ran on this line
    bool m_lineStarted = false;
    bool m_synced = false; // B/F/E/Q/U/D: a sync preceded the <cr>
    // TG: register being edited, value applied by a sign.
    char m_register = 0;
    bool m_gainApplied = false;

    // Program execution.
    bool m_running = false;
    std::size_t m_pc = 0;
    std::vector<std::size_t> m_calls;           // F return points
    std::array<std::uint32_t, 4> m_counters{};  // default, X, Y, Z
    std::optional<std::int64_t> m_loopOverride; // interactive L<label><count>

    Pmc960Wait m_wait = Pmc960Wait::None;
    bool m_waitEndsCommand = false;
    std::int64_t m_now_us = 0;
    std::int64_t m_waitUntil_us = 0;
    bool m_stepGranted = false;

    static constexpr std::size_t kCallDepth = 16;
};

} // namespace drive_core::pmc960
