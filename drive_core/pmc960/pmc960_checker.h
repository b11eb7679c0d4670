// Static diagnostics for a PMC-960 program buffer, for the IDE's editor: every line is read by the MPL
// interpreter the simulated controller runs (as program execution, in a scratch controller, so there is one
// parser, not a copy), keeping the errors that depend on the text rather than on the controller's state,
// plus what the program-mode editor refuses, the buffer's capacity and labels no line defines.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace drive_core::pmc960 {

struct Diagnostic {
    int line = 0;        // 1-based editor line
    int column = 0;      // 0-based byte column of the character the controller refuses; a refusal at the
                         // line's <cr> is at the column after the line's last stored character
    int code = 0;        // the controller's #xx code (0xA1); 0 when it gives none (the editor's BELL)
    std::string message; // the catalog's text for the code, or what the editor does
};

// text: the editor's text, lines separated by LF, CR LF or CR. Stored as the download stores it (spaces and
// tabs dropped, empty lines left out, each line ended by CR). Diagnostics in line, then column order.
std::vector<Diagnostic> checkProgram(std::string_view text);

} // namespace drive_core::pmc960
