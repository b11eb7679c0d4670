// The simulated ORMEC PMC-960: its serial input layer (the 1DH attention byte, status polls b f g h i m s v
// answered at any time, <attn><ID> talker selection, 1DH doubling, ESC, autobaud, the communications
// checksum), its output protocol (echo, CR LF <axis> } prompts, #xx errors, held async E-codes, % streams,
// P-mode editing and listings), machine I/O and power-up. The MPL itself is Pmc960Interpreter's.
#pragma once

#include "drive_core/bds5/bds5_uart.h"
#include "drive_core/drive.h"
#include "pmc960_editor.h"
#include "pmc960_interpreter.h"
#include "pmc960_simulator_controls.h"
#include "pmc960_state.h"

#include <cstdint>
#include <optional>
#include <string>

namespace drive_core::pmc960 {

// The firmware identifier N<cr> prints (L1357; its text is not in the seed).
inline constexpr std::string_view kFirmwareId = "PMC-960 MPL (SERVODESK SIMULATION)";

// Machine lines besides IN15'..IN00' (setInput) — true = asserted.
enum class Pmc960Line { Estop, Fault, Break, DriveReady, Sensor, Exec, Start };

class Pmc960Drive final : public Drive, private Pmc960Sink {
public:
    Pmc960Drive();

    DriveFamily family() const override { return DriveFamily::Pmc960; }
    void powerUp() override;
    void receive(std::string_view bytes) override;
    std::string takeTransmitted() override;
    void step(Microseconds dt) override;
    Microseconds now() const override { return m_time; }
    void setLineRateLimited(bool limited) override { m_uart.setUnlimited(!limited); }

    // Inputs 1..16 are IN00'..IN15', outputs 1..16 OUT00'..OUT15'; on = asserted (pin low).
    int inputCount() const override { return 16; }
    int outputCount() const override { return 16; }
    void setInput(int number, bool on) override;
    bool input(int number) const override;
    bool output(int number) const override;

    void setLine(Pmc960Line line, bool asserted);
    SimulatorControls* controls() override { return &m_controls; }
    // ADDR4'..ADDR0' as a 5-bit number, bit k = ADDRk' asserted; START' then runs label 40H + N (5.9).
    void setAddress(int address) { m_address = address & 0x1F; }
    // Wired to a multidrop RS-422 line with THI = id, as a machine builder sets each axis once (THI is in the
    // parameter table, kept over power cycles). From the next power-up the drive is a listener until
    // <attn><id> makes it the talker, and a talker deselected drops what it had not sent (DECISIONS.md).
    void joinBus(char id);
    bool onBus() const { return m_onBus; }
    // The optional EPROM in socket U46 (5.10): copied at power-up and N* if it begins with "@PROGRAM".
    void setEprom(std::string image) { m_eprom = std::move(image); }

    // The optional overrun model (digest §9.6): bytes cross the wire at the baud rate into the 8251A's
    // one-character buffer, which the firmware reads only when it polls; after a motion trigger (+ -) it
    // does not poll for kBusyAfterTrigger. A byte landing on a full buffer overwrites it (the earlier one
    // is lost, L2523). clearToSend() is CTS: true while the buffer is empty. Off by default.
    void setOverrunModel(bool on) { m_overrunModel = on; }
    bool clearToSend() const { return !m_overrunModel || !m_holdingFull; }
    // No byte of the host's is still on its way (received, not yet in the buffer).
    bool lineIdle() const { return m_received.empty(); }
    int overruns() const { return m_overruns; }
    static constexpr std::int64_t kBusyAfterTrigger_us = 5000;

    // The 16-bit sum of received bytes since the last <attn>h (5.3.6, digest §4.8).
    std::uint16_t checksum() const { return m_checksum; }
    bool talker() const { return m_talker; }
    bool sciEstablished() const { return m_established; }
    int baudRate() const { return m_uart.baud(); }
    const Pmc960State& state() const { return m_state; }
    Pmc960State& state() { return m_state; }
    const Pmc960Interpreter& interpreter() const { return m_interpreter; }

private:
    enum class Mode { Command, Editor, Listing, Stream };

    // Pmc960Sink
    void send(std::string_view bytes) override;
    void raise(int code) override;
    void commandDone() override;
    void enterEditor(std::size_t cursor) override;
    void listProgram(bool lineByLine) override;
    void stream(std::string command, int period_ms) override;
    void softwareReset() override;
    void autobaud() override;

    void inputByte(char c);
    void deliver(char c);
    void poll(char letter);
    void prompt();
    void reset(bool powerCycle);
    void takeSnapshot(int code);
    void tick(std::int64_t dt_us);
    void listNextLine();
    void emergencyStop();
    void overrunStep(std::int64_t dt_us);

    Pmc960State m_state;
    Pmc960Interpreter m_interpreter{m_state, *this};
    Pmc960Editor m_editor{m_state.program};
    bds5::Bds5Uart m_uart;
    std::string m_received;
    Mode m_mode = Mode::Command;
    bool m_attention = false;
    bool m_talker = true;
    bool m_onBus = false;
    bool m_established = true;
    std::uint16_t m_checksum = 0;
    std::optional<int> m_heldError; // host mode: the first async error, sent before the next prompt
    std::string m_streamCommand;
    std::int64_t m_streamPeriod_us = 100000;
    std::int64_t m_nextStream_us = 0;
    std::size_t m_listPosition = 0;
    bool m_estopStopping = false;
    int m_address = 0;
    std::string m_eprom;
    bool m_overrunModel = false;
    bool m_holdingFull = false;
    char m_holding = 0;
    double m_wireCredit = 0;
    std::int64_t m_busyUntil_us = 0;
    int m_overruns = 0;
    Microseconds m_time{0};
    Pmc960SimulatorControls m_controls{*this};
};

} // namespace drive_core::pmc960
