// StepTraceParser: reads the BDS5's output stream and tells which program line is about to run while the
// drive single-steps (the line's text, then the s--> prompt) or traces (t... + the line's text), when a
// RUN starts and when the program is over. Pure logic over bytes; the highlighter maps it to the editor.
#pragma once

#include <QByteArray>
#include <QString>

#include <vector>

namespace app {

class StepTraceParser {
public:
    struct Event {
        enum class Kind {
            Started,    // RUN [label] echoed at the interactive prompt; label -1 for RUN alone
            AboutToRun, // text: the program line as the drive shows it (indentation and comment kept)
            Paused,     // monitor mode (==>): the program waits; nothing runs
            Ended,      // the interactive prompt is back: no program line is about to run
        };
        Kind kind;
        QString text;
        int label = -1;
        bool stepping = false; // AboutToRun: shown at a single-step prompt (false: a trace line)
    };

    // Feeds bytes as the drive sent them; returns what they reveal, in order.
    std::vector<Event> feed(const QByteArray& bytes);
    void reset() { *this = StepTraceParser(); }

private:
    void endLine(std::vector<Event>& events);
    void prompt(const QString& prompt, std::vector<Event>& events);

    QString m_line;              // the line being received (no CR/LF)
    QString m_promptInLine;      // the prompt that began m_line; the rest of m_line is the echo
    QString m_lastText;          // the last non-empty line since the previous prompt
    bool m_afterStepPrompt = false; // the previous prompt was a single-step prompt...
    bool m_stepEchoTyped = false;   // ...and a command (not a bare Enter) was typed at it
};

} // namespace app
