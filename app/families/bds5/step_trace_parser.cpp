// StepTraceParser: prompts, echoes and trace prefixes in the drive's output.
#include "step_trace_parser.h"

#include "serialport/bds5_protocol.h"

#include <QRegularExpression>

namespace app {

namespace {
// Trace prefixes (Table 5.1, L5763-5771; seed-bds5 §2.3): t... t.A. t.B. t.C. t.V. t.*. and the COM
// documents' t.. ; multidrop ID + "t." (At.). Ch.5 prints them upper case (T...).
const QRegularExpression kTrace(QStringLiteral("^(?:[tT]\\.[.ABCV*]\\.|[tT]\\.\\.|[0-9A-Z][tT]\\.)(.*)$"));
const QRegularExpression kRun(QStringLiteral("^\\s*RUN(?:\\s+(\\d+))?\\s*(?:;.*)?$"),
                              QRegularExpression::CaseInsensitiveOption);
} // namespace

std::vector<StepTraceParser::Event> StepTraceParser::feed(const QByteArray& bytes) {
    std::vector<Event> events;
    for (const char byte : bytes) {
        switch (byte) {
        case '\r':
            break; // every line ends CR LF; the LF ends it
        case '\n':
            endLine(events);
            break;
        case '\b':
            m_line.chop(1);
            break;
        default:
            if (uchar(byte) < 0x20) break; // BEL before ERR lines, other controls
            m_line += QChar(char16_t(uchar(byte)));
            // A prompt is the start of a line; the drive then sends nothing until a CR (rule 4).
            if (byte == '>' && m_promptInLine.isEmpty()) {
                if (const auto p = serialport::trailingPrompt(QStringLiteral("\r\n") + m_line)) {
                    m_promptInLine = *p;
                    prompt(*p, events);
                }
            }
            break;
        }
    }
    return events;
}

void StepTraceParser::endLine(std::vector<Event>& events) {
    const QString line = std::exchange(m_line, {});
    if (!m_promptInLine.isEmpty()) { // the prompt, then what the user typed at it (echoed)
        const QString echo = line.mid(m_promptInLine.size());
        const auto mode = serialport::modeOfPrompt(std::exchange(m_promptInLine, {}));
        if (mode == serialport::Bds5Mode::SingleStep) m_stepEchoTyped = !echo.trimmed().isEmpty();
        if (mode == serialport::Bds5Mode::Interactive) {
            if (const auto run = kRun.match(echo); run.hasMatch()) {
                const QString label = run.captured(1);
                events.push_back({Event::Kind::Started, {}, label.isEmpty() ? -1 : label.toInt()});
            }
        }
        return;
    }
    if (const auto trace = kTrace.match(line); trace.hasMatch()) {
        events.push_back({Event::Kind::AboutToRun, trace.captured(1), -1, false});
        return;
    }
    if (!line.trimmed().isEmpty()) m_lastText = line;
}

void StepTraceParser::prompt(const QString& p, std::vector<Event>& events) {
    const QString shown = std::exchange(m_lastText, {});
    const bool wasStep = std::exchange(m_afterStepPrompt, false);
    switch (serialport::modeOfPrompt(p)) {
    case serialport::Bds5Mode::SingleStep:
        m_afterStepPrompt = true;
        // After a monitor command typed at the step prompt (P X1) the drive only prompts again.
        if (!(wasStep && m_stepEchoTyped) && !shown.isEmpty())
            events.push_back({Event::Kind::AboutToRun, shown, -1, true});
        break;
    case serialport::Bds5Mode::Monitor:
        events.push_back({Event::Kind::Paused, {}});
        break;
    case serialport::Bds5Mode::Interactive:
        events.push_back({Event::Kind::Ended, {}});
        break;
    default:
        break;
    }
    m_stepEchoTyped = false;
}

} // namespace app
