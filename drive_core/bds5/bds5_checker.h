// Static diagnostics for a BDS5 program, for the IDE's editor: every line goes through the same lexer and
// interpreter the simulated drive uses (executed in a scratch drive state, so there is one parser, not a
// copy), keeping the errors that depend on the text rather than on the drive's state, plus the
// program-wide checks RUN makes (labels used twice, ERROR$ not last, jumps to missing labels).
#pragma once

#include <string>
#include <vector>

namespace drive_core::bds5 {

struct Diagnostic {
    int line = 0;        // 1-based program line
    int column = 0;      // 0-based column of the offending entry (0 when the whole line)
    int length = 0;      // characters to underline (0: to the end of the line)
    int code = 0;        // the drive's error number; 0 for editor-only advice (line too long)
    std::string entry;   // the offending entry, as the drive would quote it
    std::string message; // the drive's text ("BAD OR OUT OF RANGE") or the advice
};

std::vector<Diagnostic> checkProgram(const std::vector<std::string>& lines);

} // namespace drive_core::bds5
