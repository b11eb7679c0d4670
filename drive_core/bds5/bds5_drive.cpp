// The simulated BDS5's serial line discipline and processor modes.
#include "bds5_drive.h"

#include "drive_core/catalog/bds5_catalog.h"

#include <algorithm>
#include <array>
#include <utility>

namespace drive_core::bds5 {

namespace {
constexpr char kBell = '\x07';
constexpr char kBackspace = '\x08';
constexpr char kEscape = '\x1b';
constexpr char kCtrlX = '\x18';
constexpr char kCtrlV = '\x16';
constexpr char kDelete = '\x7f';
constexpr std::string_view kCrLf = "\r\n";
// Single-drop prompts (Table 2.2, §2.3); multidrop prefixes come with the serial issue.
constexpr std::string_view kInteractivePrompt = "-->";
constexpr std::string_view kMonitorPrompt = "==>";
constexpr std::string_view kLoadPrompt = "l->";
// Error lines after a command, or out of a running program, follow CR LF LF (L9802-9806, L9857-9861).
constexpr std::string_view kErrorPreamble = "\r\n\n";
// The dedicated inputs (L820-836).
constexpr std::array<std::string_view, 7> kDedicatedInputs{"REMOTE", "HOME", "CYCLE", "LIMIT",
                                                           "MOTION", "GATE", "MANUAL"};

// How many leading bytes are printable (space to '~'): typed text, which handleText takes as one run.
// No coverage callbacks: one comparison a typed byte, and handleByte keeps every other character's path
// (not inlined: coverage is added after inlining, and would reach the loop in step()).
[[gnu::noinline]] SERVODESK_NO_COVERAGE std::size_t textRun(std::string_view bytes) {
    std::size_t n = 0;
    while (n < bytes.size() && static_cast<unsigned char>(bytes[n]) >= 0x20 &&
           static_cast<unsigned char>(bytes[n]) < 0x7f)
        ++n;
    return n;
}
} // namespace

Bds5Drive::Bds5Drive() {
    m_executor.setLineHook(
        [this](TaskLevel level, int line, std::string& out) { return beforeLine(level, line, out); });
}

void Bds5Drive::powerUp() {
    // Power lost in the middle of a change to program memory (editor, >BDS) leaves it corrupt (L3712).
    if (m_powered && (m_mode == Bds5DriveMode::Editor || (m_mode == Bds5DriveMode::ProgramLoad && m_loadStarted)))
        m_state.program.setCorrupt(true);
    // Inputs are wires, not memory: a power cycle does not change what they read. I1-I16 and the dedicated
    // inputs, resolved once (a drive powers up for every input the fuzzer runs).
    constexpr std::size_t kPins = kInputCount + kDedicatedInputs.size();
    static const auto pins = [] {
        std::array<catalog::bds5::VariableRef, kPins> refs{};
        for (int i = 1; i <= kInputCount; ++i)
            refs[std::size_t(i - 1)] = *catalog::bds5::findVariable("I" + std::to_string(i));
        for (std::size_t i = 0; i < kDedicatedInputs.size(); ++i)
            refs[kInputCount + i] = *catalog::bds5::findVariable(kDedicatedInputs[i]);
        return refs;
    }();
    std::array<std::int32_t, kPins> inputs{};
    for (std::size_t i = 0; i < kPins; ++i) inputs[i] = m_state.variables.readUser(pins[i]);
    m_state.variables.powerUp();
    m_state.recorder.clear(); // the RECORD buffer is cleared at power-up (Table 3.2 notes)
    if (m_poweredBefore)
        for (std::size_t i = 0; i < kPins; ++i) m_state.variables.set(pins[i], inputs[i]);
    m_poweredBefore = true;
    m_state.enabled = false;
    m_state.servo.powerUp();
    m_rotary.reset();
    m_servoRemainder = Microseconds{0};
    logError(m_state, 199); // DRIVE POWERED UP is logged at every power-up (L6118, L7503)
    m_executor.stop();
    m_mode = Bds5DriveMode::Interactive;
    m_received.clear();
    m_line.clear();
    m_heldErrors.clear();
    m_time = Microseconds{0};
    m_powered = true;
    m_promptPending = m_breakPending = false;
    // Autobaud (digest §2.2): MOTION off at power-up (which also forces ADDR=0), ABAUD on with ADDR 0, or
    // an invalid BAUD (ERR 103, history only). ABAUD on with ADDR set is ERR 104, history only.
    bool autobaud = false;
    if (!switchOn(Switch::Motion, true)) {
        m_state.variables.set("ADDR", 0);
        autobaud = true;
    }
    const bool abaud = switchOn(Switch::Abaud, false);
    if (abaud && addressId())
        logError(m_state, 104);
    else if (abaud)
        autobaud = true;
    if (!chooseBaudRate()) autobaud = true;
    m_port.powerUp(addressId(), autobaud, m_time);
    m_uart.setMutedFromNow(!m_port.transmits());
    // Multitasking and POWER-UP$ wait until communications are established (L1919, L4559-4567).
    if (!autobaud) establishCommunications();
}

// Sign-on, then POWER-UP$ or the prompt (L4929-4944).
void Bds5Drive::establishCommunications() {
    if (switchOn(Switch::Msg, true)) {
        transmit(kCrLf);
        transmit(kSignOn);
        transmit(kCrLf);
    }
    if (m_state.program.corrupt()) { // reported at power-up; POWER-UP$ does not run (L7513)
        logError(m_state, 202);
        sendError(Bds5Error{202, {}, 0}, "");
        return sendPrompt();
    }
    if (const auto line = m_state.program.dedicatedLine(DedicatedLabel::PowerUp); line && !m_state.program.check()) {
        transmit("EXECUTING POWER-UP LABEL\r\n"); // L4939-4944
        m_executor.start(*line, m_time);
        m_mode = Bds5DriveMode::Running;
        return;
    }
    sendPrompt();
}

void Bds5Drive::receive(std::string_view bytes) {
    m_received.append(bytes);
}

std::string Bds5Drive::takeTransmitted() {
    return m_uart.takeSent();
}

void Bds5Drive::step(Microseconds dt) {
    m_time += dt;
    if (!m_powered) return;
    tickTimers(dt);
    // The serial watchdog: no CR for WTIME ms with WATCH on is ERR 105, break and disable (L5328-5342).
    static const auto watch = *catalog::bds5::findVariable("WATCH");
    static const auto wtime = *catalog::bds5::findVariable("WTIME");
    static const auto serial = *catalog::bds5::findVariable("SERIAL");
    if (m_port.watchdogExpired(m_time, m_state.variables.read(watch) != 0, m_state.variables.readUser(wtime)))
        raiseFault(105);
    // Taken in place, so the buffer keeps its room from step to step (nothing handleByte does receives).
    // Runs of typed characters go in one piece (a flood was a UART write and a coverage-traced pass through
    // handleByte per character, issue 20); what the port or the line discipline acts on goes byte by byte.
    const std::string_view received = m_received;
    for (std::size_t i = 0; i < received.size();) {
        const std::size_t run = m_port.passesText() ? textRun(received.substr(i)) : 0;
        if (run == 0) {
            handleByte(received[i++]);
            continue;
        }
        handleText(received.substr(i, run));
        i += run;
    }
    m_received.clear();
    runServo(dt); // profile, loops, plant, faults and RECORD, every 1 ms (bds5_drive_servo.cpp)
    if (m_executor.running()) runProgram();
    m_uart.advance(dt);
    m_state.variables.set(serial, m_uart.busy() ? 0 : 1); // SERIAL is ON when the port is idle (L4437)
}

// TMR1-TMR4 count down every millisecond and stop at 0 (L5775-5800).
void Bds5Drive::tickTimers(Microseconds dt) {
    m_timerRemainder += dt;
    const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(m_timerRemainder);
    if (ms.count() == 0) return;
    m_timerRemainder -= ms;
    static const std::array timers{*catalog::bds5::findVariable("TMR1"), *catalog::bds5::findVariable("TMR2"),
                                   *catalog::bds5::findVariable("TMR3"), *catalog::bds5::findVariable("TMR4")};
    for (const auto& ref : timers) {
        const std::int64_t value = m_state.variables.read(ref);
        m_state.variables.set(ref, std::int32_t(std::max<std::int64_t>(0, value - ms.count())));
    }
}

// The pins are the I1-I16 / O1-O8 switches and the IN / OUT words (I1 = bit 0, L1800-1895).
void Bds5Drive::setInput(int number, bool on) {
    if (number < 1 || number > kInputCount) return;
    m_state.variables.set("I" + std::to_string(number), on ? 1 : 0);
}

bool Bds5Drive::setDedicatedInput(std::string_view name, bool on) {
    for (const std::string_view dedicated : kDedicatedInputs) {
        if (name != dedicated) continue;
        m_state.variables.set(name, on ? 1 : 0);
        return true;
    }
    return false;
}

bool Bds5Drive::input(int number) const {
    return number >= 1 && number <= kInputCount && m_state.variables.read("I" + std::to_string(number)).value_or(0);
}

bool Bds5Drive::output(int number) const {
    return number >= 1 && number <= kOutputCount && m_state.variables.read("O" + std::to_string(number)).value_or(0);
}

void Bds5Drive::raiseFault(int code) {
    logError(m_state, code);
    const auto* info = catalog::bds5::findError(code);
    if (info && info->severity >= catalog::bds5::Severity::Disable) { // level 3: disable, FAULT latch
        m_state.enabled = false;
        m_state.variables.set("FAULT", 1);
        m_state.motion.halt(); // disabled: the motor coasts
    } else if (info && info->severity >= catalog::bds5::Severity::Break) {
        m_state.motion.stop(m_state.variables); // level 2: stop at AMAX (L2231)
    }
    const Bds5Error error{code, {}, 0};
    if (m_executor.running())
        programStopped(ProgramStop::Error, error); // faults break the program
    else if (m_promptPending)
        m_heldErrors.push_back(error);
    else
        sendError(error, kErrorPreamble);
}

void Bds5Drive::handleByte(char c) {
    switch (m_port.accept(c, m_time)) {
    // Muting starts and ends with what is written from now on: the echo sent before a '\' still goes out,
    // and what the axis printed asleep stays unsent after it wakes (L5428).
    case Bds5Port::Verdict::Drop: m_uart.setMutedFromNow(!m_port.transmits()); return;
    case Bds5Port::Verdict::AutobaudDone:
        m_uart.setMutedFromNow(!m_port.transmits());
        return establishCommunications();
    case Bds5Port::Verdict::Woken: // "\A" answers CR LF and the prompt (L10015-10028)
        m_uart.setMutedFromNow(false);
        transmit(kCrLf);
        m_promptPending = false;
        return sendPrompt();
    case Bds5Port::Verdict::Process: break;
    }
    if (c == kCtrlX) return handleBreakCharacter();
    if (c == kEscape) return handleEscape();
    if (c == kCtrlV) return m_executor.fireVariableTask(); // the VARIABLE$ task (L4818)
    // Run mode has no prompt: the drive takes no input but its attention characters, unless an INPUT
    // waits for an answer (L1254).
    if (m_mode == Bds5DriveMode::Running && !m_state.pendingInput) return;
    const bool echo = switchOn(Switch::Echo, true);
    switch (c) {
    case '\r':
        if (echo) transmit(kCrLf);
        endOfLine();
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
        if (!m_uart.busy()) transmit(std::string_view(&kBell, 1)); // one bell at a time: the queue stays bounded
        return;
    }
    m_line.push_back(c);
    if (echo) transmit(std::string_view(&c, 1));
}

// A run of printable characters the port passes on (Bds5Port::passesText): exactly what handleByte does
// with each of them in turn, but the line grows and the echo is written once. Nothing in the run changes the
// mode, the ECHO switch or the port, so they are read once.
void Bds5Drive::handleText(std::string_view text) {
    if (m_mode == Bds5DriveMode::Running && !m_state.pendingInput) return;
    const std::size_t room = m_line.size() < std::size_t(kMaxLineLength) ? kMaxLineLength - m_line.size() : 0;
    const std::string_view kept = text.substr(0, room);
    m_line.append(kept);
    if (!kept.empty() && switchOn(Switch::Echo, true)) transmit(kept);
    // Past 80 characters each one rings while the transmitter is idle: one bell, as a rate-limited port
    // is busy once it holds it; an unlimited port (nothing queued) rings for every one.
    for (std::size_t i = kept.size(); i < text.size() && !m_uart.busy(); ++i) transmit(std::string_view(&kBell, 1));
}

// Esc (§2.5): interactive — like CR; run — enter monitor mode; monitor — back to run; load — end of load.
void Bds5Drive::handleEscape() {
    m_line.clear();
    const bool messages = switchOn(Switch::Msg, true);
    switch (m_mode) {
    case Bds5DriveMode::Interactive:
        // Esc stops a <BDS or DUMP listing still on its way out (L5350); chosen: the rest is dropped.
        if (m_uart.busy() && m_promptPending) m_uart.discard();
        transmit(kCrLf);
        m_promptPending = false;
        sendHeldErrors("");
        sendPrompt();
        return;
    case Bds5DriveMode::SingleStep: // Esc twice leaves single-step: SS off, monitor, then run (L5682)
        m_state.variables.set("SS", 0);
        m_stepGranted = true; // the line shown runs when the program goes on
        [[fallthrough]];
    case Bds5DriveMode::Running:
        if (switchOn(Switch::Trc, false)) m_state.variables.set("TRC", 0); // Esc in trace: monitor, TRC off
        transmit(messages ? "\r\n\nENTER MONITOR MODE. PUSH ESCAPE TO EXIT\r\n" : "\r\n"); // L9757-9776
        m_mode = Bds5DriveMode::Monitor;
        sendPrompt();
        return;
    case Bds5DriveMode::Monitor:
        if (m_breakPending) { // the program has already stopped: Esc answers with the held news
            transmit(kCrLf);
            m_promptPending = false;
            sendHeldErrors("\n");
            m_mode = Bds5DriveMode::Interactive;
            m_breakPending = false;
            sendPrompt();
            return;
        }
        // The manual prints the leave-monitor answer as "<cr><lf>ENTER MONITOR MODE." (L9767-9768).
        transmit(messages ? "\r\nENTER MONITOR MODE." : "\r\n");

        m_promptPending = false;
        m_mode = Bds5DriveMode::Running;
        m_executor.resume(m_time);
        return;
    case Bds5DriveMode::ProgramLoad:
        transmit(kCrLf);
        m_mode = Bds5DriveMode::Interactive;
        sendPrompt();
        return;
    case Bds5DriveMode::Editor: return editorReply(m_editor.escape());
    }
}

// ^X: STOP + BREAK from any mode, even while a program runs (L2233-2235, L9868).
void Bds5Drive::handleBreakCharacter() {
    m_line.clear();
    m_state.motion.stop(m_state.variables); // ^X is S + B
    if (m_mode == Bds5DriveMode::Running || m_mode == Bds5DriveMode::Monitor || m_mode == Bds5DriveMode::SingleStep) {
        m_executor.stop();
        m_mode = Bds5DriveMode::Interactive;
        m_breakPending = false;
        m_promptPending = false;
        sendPrompt();
    }
}

void Bds5Drive::endOfLine() {
    // The line moves to m_taken and the next one is typed into m_taken's old room.
    m_taken.swap(m_line);
    m_line.clear();
    const std::string& line = m_taken;
    m_promptPending = false;
    if (m_mode == Bds5DriveMode::ProgramLoad) return loadLine(line);
    if (m_mode == Bds5DriveMode::Editor) return editorReply(m_editor.line(line));
    if (m_mode == Bds5DriveMode::Running) return inputLine(line);
    if (!m_heldErrors.empty() || m_breakPending) {
        // A command typed while an error waits is ignored (L9721-9739, L9921-9935).
        const bool typed = line.find_first_not_of(" \t") != std::string::npos;
        if (typed && !m_heldErrors.empty()) transmit("ERROR MSG WAITING--COMMAND IGNORED\r\n\r\n\n");
        sendHeldErrors(m_mode == Bds5DriveMode::Monitor && !typed ? "\n" : "");
        if (m_breakPending) {
            m_breakPending = false;
            m_mode = Bds5DriveMode::Interactive;
        }
        sendPrompt();
        return;
    }
    if (m_mode == Bds5DriveMode::Monitor || m_mode == Bds5DriveMode::SingleStep) return monitorLine(line);
    interactiveLine(line);
}

void Bds5Drive::interactiveLine(const std::string& line) {
    // Lexed and answered into buffers kept from line to line: every typed line comes here.
    if (const auto error = lexLine(line, m_lexed)) {
        logError(m_state, error->code);
        sendError(*error, kErrorPreamble);
        return sendPrompt();
    }
    m_answer.clear();
    const Outcome outcome = m_interpreter.execute(m_lexed.entries, ExecContext{Origin::Terminal, 0}, m_answer);
    transmit(m_answer);
    if (outcome.error) {
        logError(m_state, outcome.error->code);
        sendError(*outcome.error, kErrorPreamble);
        return sendPrompt();
    }
    applyTerminalFlow(outcome);
}

void Bds5Drive::applyTerminalFlow(const Outcome& outcome) {
    switch (outcome.flow) {
    case Flow::Run: return runProgram(outcome.target);
    case Flow::Edit: m_mode = Bds5DriveMode::Editor; return editorReply(m_editor.enter());
    case Flow::Load:
        // A password set with the editor's PASS must be given: ERR 110, program unchanged (L7123-7134).
        if (!m_state.program.password().empty() && outcome.text != m_state.program.password()) {
            logError(m_state, 110);
            sendError(Bds5Error{110, ">BDS", 0}, kErrorPreamble);
            return sendPrompt();
        }
        m_mode = Bds5DriveMode::ProgramLoad;
        m_loadStarted = false;
        return sendPrompt();
    case Flow::List:
        for (const std::string& l : m_state.program.lines()) {
            transmit(l);
            transmit(kCrLf);
        }
        return sendPrompt();
    default: return sendPrompt();
    }
}

void Bds5Drive::loadLine(std::string line) {
    if (!m_loadStarted) { // program memory is erased on the first CR-terminated line (L9957)
        m_state.program.clear();
        m_state.program.setCorrupt(false); // >BDS resets "USER PROGRAM CORRUPT" and keeps the password
        m_loadStarted = true;
    }
    if (!m_state.program.append(std::move(line))) {
        logError(m_state, 86);
        sendError(Bds5Error{86, ">BDS", 0}, kErrorPreamble); // USER PROGRAM FULL (L7396)
    }
    sendPrompt();
}

void Bds5Drive::editorReply(const Bds5ResidentEditor::Reply& reply) {
    std::string output = reply.output;
    for (const char* p : {"e->", "i->", "f->", "c->"}) // the editor speaks single-drop; multidrop adds the ID
        if (output.ends_with(p)) output.replace(output.size() - 3, 3, m_port.prompt(p));
    transmit(output);
    if (const auto code = m_editor.takeError()) logError(m_state, *code); // ERR 86 / 110 go to ERR HIST
    if (reply.exited) {
        m_mode = Bds5DriveMode::Interactive;
        return sendPrompt();
    }
    m_promptPending = true;
}

void Bds5Drive::sendError(const Bds5Error& error, std::string_view preamble) {
    transmit(preamble);
    std::string& line = m_errorLine; // reused: a flood of bad commands is a flood of error lines
    line.assign(1, kBell);
    appendError(line, error);
    if (switchOn(Switch::Dep, false) && line.size() > 1 + 40)
        line.resize(1 + 40); // the bell and the DEP-01's 40 columns (L6102-6108)
    line += kCrLf;
    transmit(line);
}

void Bds5Drive::sendHeldErrors(std::string_view preamble) {
    for (const Bds5Error& e : m_heldErrors) sendError(e, preamble);
    m_heldErrors.clear();
}

void Bds5Drive::sendPrompt() {
    // ADDR set from the terminal takes effect at once (L5424): a new ID sleeps until '\' + ID wakes it
    // (L5449-5451), so this prompt is not sent; the echo of the ADDR line before it still is.
    m_port.setAxis(addressId());
    m_uart.setMutedFromNow(!m_port.transmits());
    if (!m_uart.atLineStart()) transmit(kCrLf); // every prompt follows CR LF (L9609)
    const std::string prompt = m_mode == Bds5DriveMode::Monitor       ? std::string(kMonitorPrompt)
                               : m_mode == Bds5DriveMode::ProgramLoad ? std::string(kLoadPrompt)
                               : m_mode == Bds5DriveMode::SingleStep  ? currentStepPrompt()
                                                                      : std::string(kInteractivePrompt);
    if (switchOn(Switch::Prompt, true)) transmit(m_port.prompt(prompt)); // PROMPT OFF: none (L1550, L5320-5326)
    m_promptPending = true;
}

void Bds5Drive::transmit(std::string_view bytes) {
    m_uart.write(bytes);
}

// The rate is fixed at power-up from BAUD; false (ERR 103, history only) if BAUD is no valid rate.
bool Bds5Drive::chooseBaudRate() {
    const std::int32_t baud = m_state.variables.read("BAUD").value_or(9600);
    const bool valid = Bds5Uart::validBaud(baud);
    if (!valid) logError(m_state, 103);
    m_uart.reset(valid ? baud : 9600);
    return valid;
}

void Bds5Drive::setAddress(char id) {
    m_state.variables.set("ADDR", std::int32_t(static_cast<unsigned char>(id)));
}

// ADDR 48-57 ('0'-'9') or 65-90 ('A'-'Z') is this axis' multidrop ID; 0 is single-drop (L5416-5424).
std::optional<char> Bds5Drive::addressId() const {
    static const auto ref = *catalog::bds5::findVariable("ADDR"); // read for every prompt
    const std::int32_t addr = m_state.variables.readUser(ref);
    if ((addr >= '0' && addr <= '9') || (addr >= 'A' && addr <= 'Z')) return char(addr);
    return std::nullopt;
}

// The switches read for every typed byte and line are looked up in the catalog once (a lookup by name
// per byte was a tenth of the input fuzzer's time, and finding the cached one by name another 4 %).
SERVODESK_NO_COVERAGE bool Bds5Drive::switchOn(Switch which, bool fallback) const {
    static const auto refs = [] {
        std::array<catalog::bds5::VariableRef, 9> r{};
        std::size_t i = 0; // in the order of enum class Switch
        for (const std::string_view n : {"ECHO", "MSG", "PROMPT", "TRC", "SS", "DEP", "MOTION", "ABAUD", "MONITOR"})
            r[i++] = catalog::bds5::findVariable(n).value_or(catalog::bds5::VariableRef{});
        return r;
    }();
    const catalog::bds5::VariableRef& ref = refs[std::size_t(which)];
    return ref.info ? m_state.variables.read(ref) != 0 : fallback;
}

} // namespace drive_core::bds5
