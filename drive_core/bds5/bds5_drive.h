// The simulated Kollmorgen BDS5: its serial port behaviour (echo, prompts, held errors) around the
// interpreter. Byte for byte what the manual's transcripts show (seed-bds5 §2.3-2.4).
#pragma once

#include "bds5_interpreter.h"
#include "drive_core/drive.h"

#include <array>
#include <string>
#include <vector>

namespace drive_core::bds5 {

// The sign-on text is not in the seed (digest §2.2); chosen to name the drive, the firmware level the
// simulator follows (v3.0.0) and that it is a simulation, so no user mistakes it for hardware.
inline constexpr std::string_view kSignOn = "BDS5 DIGITAL SERVO DRIVE  V3.0.0  (SERVODESK SIMULATION)";

class Bds5Drive final : public Drive {
public:
    Bds5Drive();

    DriveFamily family() const override { return DriveFamily::Bds5; }
    void powerUp() override;
    void receive(std::string_view bytes) override;
    std::string takeTransmitted() override;
    void step(Microseconds dt) override;
    Microseconds now() const override { return m_time; }

    int inputCount() const override { return int(m_inputs.size()); }
    int outputCount() const override { return int(m_outputs.size()); }
    void setInput(int number, bool on) override;
    bool input(int number) const override;
    bool output(int number) const override;

    // An asynchronous fault (feedback loss, over-speed, ...): logged at once, printed when the host
    // next sends CR or Esc, never while a prompt is pending (L9712-9739).
    void raiseFault(int code);

    bool promptPending() const { return m_promptPending; }
    const Bds5State& state() const { return m_state; }

private:
    void handleByte(char c);
    void endOfLine();
    void abortLine();
    void sendHeldErrors();
    void sendPrompt();
    void transmit(std::string_view bytes);
    bool switchOn(std::string_view name, bool fallback) const;

    Bds5State m_state;
    Bds5Interpreter m_interpreter{m_state};
    std::string m_received;    // UART receive buffer, not yet processed
    std::string m_transmitted; // UART transmit buffer, not yet taken by the host side
    std::string m_line;        // the instruction being typed
    std::vector<Bds5Error> m_heldErrors;
    bool m_promptPending = false;
    bool m_powered = false;
    Microseconds m_time{0};
    std::array<bool, 16> m_inputs{}; // I1-I16
    std::array<bool, 8> m_outputs{}; // O1-O8
};

} // namespace drive_core::bds5
