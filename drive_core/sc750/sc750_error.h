// A compile error: where (1-based line and column), the text it was near, and what is wrong. The first
// error aborts a compile; the IDE highlights `line`. Carried by value, never thrown across into Qt code.
#pragma once

#include <string>

namespace drive_core::sc750 {

struct CompileError {
    int line = 0;
    int column = 0;
    std::string near; // the source text at the error ("" at end of file)
    std::string message;

    // "LINE 12 COL 5 NEAR 'GOTO': label Loop2 is not defined"
    std::string text() const {
        return "LINE " + std::to_string(line) + " COL " + std::to_string(column) + " NEAR '" + near + "': " + message;
    }
};

// Thrown inside the compiler stages only; compile() turns it into a CompileError result.
struct CompileFailure {
    CompileError error;
};

} // namespace drive_core::sc750
