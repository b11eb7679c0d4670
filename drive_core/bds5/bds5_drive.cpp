// The simulated BDS5's serial line discipline: echo, CR handling, prompts, held errors.
#include "bds5_drive.h"

#include <utility>

namespace drive_core::bds5 {

namespace {
constexpr char kBell = '\x07';
constexpr char kBackspace = '\x08';
constexpr char kEscape = '\x1b';
constexpr char kCtrlX = '\x18';
constexpr char kDelete = '\x7f';
constexpr std::string_view kCrLf = "\r\n";
constexpr std::string_view kPrompt = "-->"; // interactive mode, single-drop (Table 2.2)
} // namespace

Bds5Drive::Bds5Drive() = default;

void Bds5Drive::powerUp() {
    m_state.variables.powerUp();
    m_state.enabled = false;
    logError(m_state, 199); // DRIVE POWERED UP is logged at every power-up (L6118, L7503)
    m_received.clear();
    m_line.clear();
    m_heldErrors.clear();
    m_outputs.fill(false);
    m_time = Microseconds{0};
    m_powered = true;
    m_promptPending = false;
    // ABAUD off and MOTION on: no autobaud, the sign-on goes out at once (digest §2.2).
    if (switchOn("MSG", true)) {
        transmit(kCrLf);
        transmit(kSignOn);
        transmit(kCrLf);
    }
    sendPrompt();
}

void Bds5Drive::receive(std::string_view bytes) { m_received.append(bytes); }

std::string Bds5Drive::takeTransmitted() { return std::exchange(m_transmitted, {}); }

void Bds5Drive::step(Microseconds dt) {
    m_time += dt;
    if (!m_powered) return;
    // The command processor handles everything received; instructions here take no simulated time yet.
    std::string bytes = std::exchange(m_received, {});
    for (const char c : bytes) handleByte(c);
}

void Bds5Drive::setInput(int number, bool on) {
    if (number >= 1 && number <= inputCount()) m_inputs[std::size_t(number - 1)] = on;
}

bool Bds5Drive::input(int number) const {
    return number >= 1 && number <= inputCount() && m_inputs[std::size_t(number - 1)];
}

bool Bds5Drive::output(int number) const {
    return number >= 1 && number <= outputCount() && m_outputs[std::size_t(number - 1)];
}

void Bds5Drive::raiseFault(int code) {
    logError(m_state, code);
    m_heldErrors.push_back(Bds5Error{code, {}, 0});
    if (!m_promptPending) sendHeldErrors();
}

void Bds5Drive::handleByte(char c) {
    const bool echo = switchOn("ECHO", true);
    switch (c) {
    case '\r':
        if (echo) transmit(kCrLf);
        endOfLine();
        return;
    case kEscape: // in interactive mode Esc answers like CR; the partial line is dropped (chosen)
        transmit(kCrLf);
        abortLine();
        return;
    case kCtrlX: // STOP + BREAK from any mode (L2233); motion is not simulated yet
        m_line.clear();
        return;
    case kBackspace:
    case kDelete: // line editing is not in the seed; chosen: erase the last character on screen
        if (!m_line.empty()) {
            m_line.pop_back();
            if (echo) transmit("\b \b");
        }
        return;
    case '\n': // a terminal sending CR LF: the LF is ignored (chosen)
        return;
    default: break;
    }
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) return;
    if (int(m_line.size()) >= kMaxLineLength) { // 80 characters an instruction: ring instead (chosen)
        transmit(std::string_view(&kBell, 1));
        return;
    }
    m_line.push_back(c);
    if (echo) transmit(std::string_view(&c, 1));
}

void Bds5Drive::endOfLine() {
    const std::string line = std::exchange(m_line, {});
    m_promptPending = false;
    if (!m_heldErrors.empty()) {
        if (line.find_first_not_of(" \t") != std::string::npos) {
            // A command typed while an error waits is ignored (L9721-9739).
            transmit("ERROR MSG WAITING--COMMAND IGNORED\r\n\r\n\n");
        }
        sendHeldErrors();
        sendPrompt();
        return;
    }
    std::string out;
    std::optional<Bds5Error> error;
    auto lexed = lexLine(line);
    if (auto* e = std::get_if<Bds5Error>(&lexed)) error = *e;
    else error = m_interpreter.execute(std::get<LexedLine>(lexed), out);
    transmit(out);
    if (error) {
        logError(m_state, error->code);
        transmit(std::string(1, kBell) + formatError(*error) + std::string(kCrLf));
    }
    sendPrompt();
}

void Bds5Drive::abortLine() {
    m_line.clear();
    m_promptPending = false;
    sendHeldErrors();
    sendPrompt();
}

void Bds5Drive::sendHeldErrors() {
    for (const Bds5Error& e : m_heldErrors) transmit(std::string(1, kBell) + formatError(e) + std::string(kCrLf));
    m_heldErrors.clear();
}

void Bds5Drive::sendPrompt() {
    // Every prompt follows a CR LF already sent; PROMPT OFF suppresses it (L1550, L5320-5326).
    if (switchOn("PROMPT", true)) transmit(kPrompt);
    m_promptPending = true;
}

void Bds5Drive::transmit(std::string_view bytes) { m_transmitted.append(bytes); }

bool Bds5Drive::switchOn(std::string_view name, bool fallback) const {
    const auto v = m_state.variables.read(name);
    return v ? *v != 0 : fallback;
}

} // namespace drive_core::bds5
