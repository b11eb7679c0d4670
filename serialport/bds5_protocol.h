// What the BDS5 sends, understood: prompts and the mode they mean, error lines. Pure functions, no I/O,
// shared by the session (and anything else that reads a BDS5 byte stream, such as the terminal).
#pragma once

#include <QString>

#include <optional>

namespace serialport {

// The processor modes a prompt reveals (seed-bds5 §2.3, §3). Run mode has no prompt.
enum class Bds5Mode { Unknown, Interactive, Monitor, SingleStep, Editor, ProgramLoad, Insert, Find, Change, Running };

QString modeName(Bds5Mode mode);

// If text (received bytes) ends with "<cr><lf>" + a prompt, the prompt ("-->", "==>", "s-->", "A->", ...).
std::optional<QString> trailingPrompt(const QString& text);
Bds5Mode modeOfPrompt(const QString& prompt);

struct Bds5ErrorLine {
    int code = 0;
    int programLine = 0; // 0 when raised interactively
    QString entry;       // the offending entry, without quotes
    QString message;     // "ZERO DIVIDE"
};

// Parses "<bell>ERR 83 LINE 2 '2'      BAD OR OUT OF RANGE" or "ERR 17 FEEDBACK LOSS".
std::optional<Bds5ErrorLine> parseErrorLine(const QString& line);

} // namespace serialport
