// The simulated Kollmorgen BDS5: its serial port behaviour (echo, prompts, held errors), its processor
// modes (interactive, run, monitor, program load) and the program executor. Byte for byte what the
// manual's transcripts show (seed-bds5 §2.3-2.6, §3).
#pragma once

#include "bds5_executor.h"
#include "bds5_interpreter.h"
#include "bds5_port.h"
#include "bds5_resident_editor.h"
#include "bds5_rotary.h"
#include "bds5_simulator_controls.h"
#include "bds5_uart.h"
#include "drive_core/drive.h"
#include "drive_core/master_signal.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace drive_core::bds5 {

// The sign-on text is not in the seed (digest §2.2); chosen to name the drive, the firmware level the
// simulator follows (v3.0.0) and that it is a simulation, so no user mistakes it for hardware.
inline constexpr std::string_view kSignOn = "BDS5 DIGITAL SERVO DRIVE  V3.0.0  (SERVODESK SIMULATION)";

enum class Bds5DriveMode { Interactive, Running, Monitor, SingleStep, ProgramLoad, Editor };

class Bds5Drive final : public Drive {
public:
    Bds5Drive();

    DriveFamily family() const override { return DriveFamily::Bds5; }
    void powerUp() override;
    // ADDR as kept in the drive's memory ('0'-'9', 'A'-'Z'; 0 for single-drop), as a machine builder sets each
    // axis of a multidrop line once: the next power-up starts in multidrop mode, asleep (L5416-5451).
    void setAddress(char id);
    void receive(std::string_view bytes) override;
    std::string takeTransmitted() override;
    void step(Microseconds dt) override;
    void setLineRateLimited(bool limited) override { m_uart.setUnlimited(!limited); }
    Microseconds now() const override { return m_time; }

    static constexpr int kInputCount = 16; // I1-I16
    static constexpr int kOutputCount = 8; // O1-O8
    int inputCount() const override { return kInputCount; }
    int outputCount() const override { return kOutputCount; }
    void setInput(int number, bool on) override;
    bool input(int number) const override;
    bool output(int number) const override;

    // The dedicated inputs: REMOTE, HOME, CYCLE, LIMIT, MOTION, GATE, MANUAL (L820-836). False if the name
    // is none of them.
    bool setDedicatedInput(std::string_view name, bool on);

    // An asynchronous fault (feedback loss, over-speed, ...): logged at once, printed when the host
    // next sends CR or Esc, never while a prompt is pending (L9712-9739).
    void raiseFault(int code);

    Bds5DriveMode mode() const { return m_mode; }
    bool promptPending() const { return m_promptPending; }
    // The UART still has bytes to send (they leave at the BAUD rate, 8N1: ten bits a character).
    bool transmitting() const { return m_uart.busy(); }
    // Characters written and not yet on the line.
    std::size_t transmitBacklog() const { return m_uart.backlog(); }
    int baudRate() const { return m_uart.baud(); }
    const Bds5State& state() const { return m_state; }
    // The bench: inputs, load, motor, master input, power (SimulatorControls).
    SimulatorControls* controls() override { return &m_controls; }

private:
    friend class Bds5SimulatorControls;
    // What the bench sets beyond the input pins.
    struct Bench {
        std::optional<double> homeAt_rev; // the HOME switch closes around this shaft position
        MasterSignal master;              // external input: counts per second, and a wave on it
        bool feedbackConnected = true;    // resolver wires; broken: ERR 17 FEEDBACK LOSS while enabled
    };
    static constexpr double kHomeWindow_rev = 1.0 / 64;

    void runServo(Microseconds dt);
    void servoTick();
    void masterInput();
    void homeAndCapture();
    void handleByte(char c);
    void handleText(std::string_view text);
    void handleEscape();
    void handleBreakCharacter();
    void endOfLine();
    void interactiveLine(const std::string& line);
    void monitorLine(const std::string& line);
    void inputLine(const std::string& line);
    Bds5Executor::LineGate beforeLine(TaskLevel level, int line, std::string& out);
    std::string currentStepPrompt() const;
    void loadLine(std::string line);
    void editorReply(const Bds5ResidentEditor::Reply& reply);
    void applyTerminalFlow(const Outcome& outcome);
    void runProgram(int label);
    void runProgram();
    void programStopped(ProgramStop stop, const std::optional<Bds5Error>& error);
    void sendError(const Bds5Error& error, std::string_view preamble);
    void sendHeldErrors(std::string_view preamble);
    void sendPrompt();
    void transmit(std::string_view bytes);
    // The switches the line discipline reads for every byte and line (the catalog's ECHO, MSG, ...).
    enum class Switch { Echo, Msg, Prompt, Trc, Ss, Dep, Motion, Abaud, Monitor };
    bool switchOn(Switch which, bool fallback) const;
    void establishCommunications();
    std::optional<char> addressId() const;
    void tickTimers(Microseconds dt);
    bool chooseBaudRate();

    Bds5State m_state;
    Bds5Interpreter m_interpreter{m_state};
    Bds5Executor m_executor{m_state, m_interpreter};
    Bds5ResidentEditor m_editor{m_state.program};
    Bds5DriveMode m_mode = Bds5DriveMode::Interactive;
    std::string m_received; // UART receive buffer, not yet processed
    Bds5Uart m_uart;
    Bds5Port m_port;
    std::string m_line;      // the instruction being typed
    std::string m_errorLine; // sendError's buffer, kept between lines
    std::vector<Bds5Error> m_heldErrors;
    // Buffers kept between lines for their room (every typed line passes through them): the line endOfLine
    // works on (it swaps with m_line), and interactiveLine's entries and answer.
    std::string m_taken;
    LexedLine m_lexed;
    std::string m_answer;
    bool m_promptPending = false;
    bool m_breakPending = false; // the program stopped while the monitor prompt was up
    bool m_stepGranted = false;  // single-step: Enter lets the shown line run
    bool m_loadStarted = false;  // >BDS: the first line erases the program (L9957)
    bool m_powered = false;
    bool m_poweredBefore = false; // inputs keep their state across later power cycles
    Microseconds m_time{0};
    Microseconds m_timerRemainder{0};
    Microseconds m_servoRemainder{0};
    bool m_motionStopped = false; // ERR 19 raised for the motion now stopping
    double m_masterFraction = 0;  // external counts not yet whole
    bool m_homeLast = false;      // HOME as last seen, for capture's edge
    double m_homeLastRev = 0;     // the shaft then (revolutions)
    Bds5Rotary m_rotary;          // ROTARY's roll-over (the fraction of a count it carries)
    Bench m_bench;
    Bds5SimulatorControls m_controls{*this};
};

} // namespace drive_core::bds5
