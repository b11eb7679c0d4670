// What the BDS5 sends, understood: prompts and the mode they mean, error lines. Pure functions, no I/O,
// shared by the session (and anything else that reads a BDS5 byte stream, such as the terminal).
#pragma once

#include <QString>

#include <optional>

namespace serialport {

// The processor modes a prompt reveals (seed-bds5 §2.3, §3). Run mode has no prompt.
// Asleep: the drive took a multidrop address (ADDR 48-57, 65-90) and answers nothing until "\" + its ID.
enum class Bds5Mode { Unknown, Interactive, Monitor, SingleStep, Editor, ProgramLoad, Insert, Find, Change, Running, Asleep };

QString modeName(Bds5Mode mode);

// If text (received bytes) ends with "<cr><lf>" + a prompt, the prompt ("-->", "==>", "s-->", "A->", ...).
std::optional<QString> trailingPrompt(const QString& text);
Bds5Mode modeOfPrompt(const QString& prompt);
// If text ends with the echo of a line that gives the drive a multidrop address ("ADDR 65" CR LF, "ADDR=48"):
// the ID the drive now sleeps under until "\" + ID wakes it (L5424-5426, L5449-5451).
std::optional<char> addressEchoEndingIn(const QString& text);

struct Bds5ErrorLine {
    int code = 0;
    int programLine = 0; // 0 when raised interactively
    QString entry;       // the offending entry, without quotes
    QString message;     // "ZERO DIVIDE"
};

// Parses "<bell>ERR 83 LINE 2 '2'      BAD OR OUT OF RANGE" or "ERR 17 FEEDBACK LOSS".
std::optional<Bds5ErrorLine> parseErrorLine(const QString& line);

// How long the drive may stay silent after a command before its answer or prompt is overdue, not counting
// the time the bytes spend on the wire (the session adds that from the baud rate). From the drive's own
// command times: a program line in load mode is stored at once, most commands take milliseconds (App. F),
// EN and TUNE take seconds. The manual gives no upper bounds; these are ServoDesk's, with margin.
int bds5CommandSilenceMs(const QString& line, Bds5Mode mode);

} // namespace serialport
