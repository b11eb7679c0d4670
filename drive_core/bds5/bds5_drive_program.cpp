// Bds5Drive, program side: RUN, the running program's output, monitor and single-step lines, trace,
// INPUT answers and how a program stops. (The serial line discipline is in bds5_drive.cpp.)
#include "bds5_drive.h"

#include <cctype>

namespace drive_core::bds5 {

namespace {
constexpr std::string_view kErrorPreamble = "\r\n\n";

char taskLetter(TaskLevel level) {
    switch (level) {
    case TaskLevel::AlarmA: return 'A';
    case TaskLevel::AlarmB: return 'B';
    case TaskLevel::AlarmC: return 'C';
    case TaskLevel::Variable: return 'V';
    case TaskLevel::Main: return '-';
    case TaskLevel::Background: return '*';
    }
    return '-';
}

// Table 5.1 (L5763-5771): single-step prompts s-A> s-B> s-C> s-V> s--> s-*>.
std::string stepPrompt(TaskLevel level) {
    return std::string("s-") + taskLetter(level) + ">";
}

// Trace prefixes t.A. t.B. t.C. t.V. t... t.*. (lower case as in Table 5.1 and the COM documents).
std::string tracePrefix(TaskLevel level) {
    const char c = taskLetter(level);
    return std::string("t.") + (c == '-' ? '.' : c) + ".";
}

// An INPUT answer: [-]digits[.digits] scaled by 10^decimals (extra decimals are cut, chosen), or
// ON/OFF/Y/N. nullopt if it is neither.
std::optional<std::int64_t> parseAnswer(std::string text, int decimals) {
    for (char& c : text) c = char(std::toupper(static_cast<unsigned char>(c)));
    if (text == "ON" || text == "Y") return 1;
    if (text == "OFF" || text == "N") return 0;
    std::size_t i = 0;
    const bool negative = !text.empty() && (text[0] == '-' || text[0] == '+') && text[i++] == '-';
    std::int64_t value = 0;
    int digits = 0;
    int fraction = -1; // digits seen after the point
    for (; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '.' && fraction < 0) {
            fraction = 0;
            continue;
        }
        if (!std::isdigit(static_cast<unsigned char>(c)) || ++digits > 12) return std::nullopt;
        if (fraction >= 0 && fraction >= decimals) continue;
        value = value * 10 + (c - '0');
        if (fraction >= 0) ++fraction;
    }
    if (digits == 0) return std::nullopt;
    for (int f = std::max(fraction, 0); f < decimals; ++f) value *= 10;
    return negative ? -value : value;
}
} // namespace

void Bds5Drive::runProgram(int label) {
    // RUN checks the program before it starts (L3746): corruption, labels used twice, labels after ERROR$.
    if (m_state.program.corrupt()) {
        logError(m_state, 202);
        sendError(Bds5Error{202, "RUN", 0}, kErrorPreamble);
        return sendPrompt();
    }
    if (const auto problem = m_state.program.check()) {
        logError(m_state, problem->code);
        sendError(*problem, kErrorPreamble);
        return sendPrompt();
    }
    std::optional<int> line; // RUN alone enables multitasking without a main routine (L4595-4601)
    if (label >= 0) {
        line = m_state.program.labelLine(label);
        if (!line) {
            logError(m_state, 70);
            sendError(Bds5Error{70, std::to_string(label), 0}, kErrorPreamble);
            return sendPrompt();
        }
    }
    m_executor.start(line, m_time);
    m_mode = Bds5DriveMode::Running;        // no prompt while the program runs
    if (switchOn(Switch::Monitor, false)) { // v3 MONITOR 1: monitor mode whenever a program starts (L9302)
        transmit(switchOn(Switch::Msg, true) ? "\r\n\nENTER MONITOR MODE. PUSH ESCAPE TO EXIT\r\n" : "");
        m_mode = Bds5DriveMode::Monitor;
        sendPrompt();
    }
}

void Bds5Drive::runProgram() {
    if (m_mode == Bds5DriveMode::SingleStep) return m_executor.resume(m_time); // waits for Enter
    m_state.serialBusy = transmitting(); // a print waits for the previous one to leave (L4637)
    const bool inputWaited = m_state.pendingInput.has_value();
    std::string out;
    std::optional<Bds5Error> error;
    const ProgramStop stop = m_executor.advance(m_time, out, error);
    if (m_mode == Bds5DriveMode::Running) transmit(out);              // program prints are suppressed in monitor mode
    if (!inputWaited && m_state.pendingInput) m_promptPending = true; // errors wait while INPUT does
    if (error && stop == ProgramStop::Running) { // a warning, or a break into ERROR$: the program goes on
        if (m_promptPending)
            m_heldErrors.push_back(*error);
        else
            sendError(*error, kErrorPreamble);
    }
    if (stop != ProgramStop::Running) return programStopped(stop, error);
    if (m_executor.paused() && m_mode == Bds5DriveMode::Running) {
        m_mode = Bds5DriveMode::SingleStep;
        sendPrompt();
    }
}

// Before each program line: the trace line, or single-step's stop before it (L5637-5712). A trace line
// is output like a print: it waits until the previous output has left (L4637), so the trace goes at the
// line's pace and the transmitter never holds more than a line (DECISIONS.md 17).
Bds5Executor::LineGate Bds5Drive::beforeLine(TaskLevel level, int line, std::string& out) {
    using Gate = Bds5Executor::LineGate;
    const bool shown = m_mode == Bds5DriveMode::Running;        // monitor mode: no display (chosen)
    const bool stepping = shown && switchOn(Switch::Ss, false); // with TRC also on, single-step wins (L1320)
    const bool tracing = shown && !stepping && switchOn(Switch::Trc, false);
    if (tracing && m_state.serialBusy) return Gate::WaitLine;
    if (m_state.traceRecording) { // v3 real-time trace: the newest 100 lines (buffer size chosen)
        m_state.traceBuffer.push_back({line, tracePrefix(level), m_state.program.line(line)});
        if (m_state.traceBuffer.size() > 100) m_state.traceBuffer.pop_front();
    }
    if (stepping) {
        if (std::exchange(m_stepGranted, false)) return Gate::Run;
        out += m_state.program.line(line) + "\r\n";
        return Gate::Pause;
    }
    if (!shown) return Gate::Run;
    m_stepGranted = false;
    if (tracing) {
        out += tracePrefix(level) + m_state.program.line(line) + "\r\n";
        m_state.serialBusy = true;
    }
    return Gate::Run;
}

std::string Bds5Drive::currentStepPrompt() const {
    return stepPrompt(m_executor.currentTask().value_or(TaskLevel::Main));
}

// A line typed at the monitor (==>) or single-step (s-->) prompt: the monitor command subset.
void Bds5Drive::monitorLine(const std::string& line) {
    const bool stepping = m_mode == Bds5DriveMode::SingleStep;
    if (stepping && line.find_first_not_of(" \t") == std::string::npos) { // Enter: run the shown line
        m_stepGranted = true;
        m_mode = Bds5DriveMode::Running;
        return m_executor.resume(m_time);
    }
    auto lexed = lexLine(line);
    std::string out;
    Outcome outcome;
    if (auto* e = std::get_if<Bds5Error>(&lexed))
        outcome.error = *e;
    else
        outcome = m_interpreter.execute(std::get<LexedLine>(lexed).entries, ExecContext{Origin::Monitor, 0}, out);
    transmit(out);
    if (outcome.error) {
        logError(m_state, outcome.error->code);
        sendError(*outcome.error, kErrorPreamble);
    }
    // S, B and K typed in monitor mode break the program: back to interactive (L9778-9797).
    if (outcome.flow == Flow::Break || outcome.flow == Flow::Stop || outcome.flow == Flow::Kill) {
        m_executor.stop();
        m_mode = Bds5DriveMode::Interactive;
    } else if (stepping && !switchOn(Switch::Ss, false)) { // SS OFF typed at the step prompt: run on
        m_stepGranted = true;
        m_mode = Bds5DriveMode::Running;
        return m_executor.resume(m_time);
    }
    sendPrompt();
}

// The operator's answer to INPUT. An empty answer keeps the value; a bad one prints the drive's error
// and asks again (the seed gives no message text; chosen: ERR 83 with the answer, then the INPUT text).
void Bds5Drive::inputLine(const std::string& line) {
    m_promptPending = false;
    const InputRequest request = *m_state.pendingInput;
    std::string answer = line;
    answer.erase(0, answer.find_first_not_of(" \t"));
    answer.erase(answer.find_last_not_of(" \t") + 1);
    if (!answer.empty()) {
        const auto value = parseAnswer(answer, request.decimals);
        const auto before = m_state.variables.read(request.variable);
        int error = 83;
        if (value && *value >= request.minimum && *value <= request.maximum)
            error = m_state.variables.write(request.variable, *value, m_state.enabled);
        if (!error && request.variable == "EXTDX" && before != m_state.variables.read(request.variable))
            switchExtendedRegisters(m_state);
        if (error) {
            sendError(Bds5Error{error, answer, 0}, "");
            transmit(request.text);
            m_promptPending = true;
            return;
        }
    }
    m_state.pendingInput.reset();
}

void Bds5Drive::programStopped(ProgramStop stop, const std::optional<Bds5Error>& error) {
    m_executor.stop();
    if (stop == ProgramStop::Kill) {
        m_state.enabled = false;
        m_state.motion.halt();
    }
    if (stop == ProgramStop::Error) m_state.motion.stop(m_state.variables); // breaking errors stop at AMAX
    if (m_mode == Bds5DriveMode::Monitor) { // the monitor prompt is up: news waits for the next CR
        if (error) m_heldErrors.push_back(*error);
        m_breakPending = true;
        return;
    }
    m_promptPending = false;
    if (error) sendError(*error, kErrorPreamble);
    m_mode = Bds5DriveMode::Interactive;
    sendPrompt();
}

} // namespace drive_core::bds5
