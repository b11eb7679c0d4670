// Where in its program a PMC-960 routine stopped on an error. The controller prints only the code (#B6); its
// error-status buffer adds the last label passed and the commands executed since (SB&, 7.17.1, L1466-1474).
// This follows the program text from that label to the command that failed. Pure; decisions in DECISIONS.md
// ("Placing a program error").
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace drive_core::pmc960 {

struct Pmc960ErrorPlace {
    std::size_t line = 0;     // 0-based index into the stored lines
    std::string command;      // the failing command as stored ("I2048+,")
    char routine = 0;         // the label of the routine holding it: the nearest @-line above it but @.
    bool afterReturn = false; // reached by following an E back to the only F that calls its routine
    bool ambiguous = false;   // several lines start with @<label>: the one taken is the likelier
};

// lines: the program as the controller stores it (no spaces, no empty lines; Pmc960Download::programLines).
// started: the label B<label> ran. lastLabel, commandsSince: SB&'s label and count; code: the error (#C2 is
// a B, F or L whose label is missing, which counted itself before it jumped). nullopt when the text
// does not lead there by straight execution: the label is not in it, or a label line, an unconditional B, F
// or Q, the end of the buffer or an E whose routine has no single caller comes first.
std::optional<Pmc960ErrorPlace> placeProgramError(const std::vector<std::string>& lines, char started, char lastLabel,
                                                  int commandsSince, int code);

// The commands of one stored line as SB counts them: a display character (? ! &) ends one, the line's CR
// the last; none on an @-line or a line of fillers ('.'). "G!V!" is {"G!", "V!"}.
std::vector<std::string> commandsOf(std::string_view line);

} // namespace drive_core::pmc960
