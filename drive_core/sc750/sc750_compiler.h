// The ServoBASIC Plus compiler: lexer -> parser -> code generator -> .BIN bytes. Stops at the first
// error and reports it with line, column and the text it was near. Pure function of its input.
#pragma once

#include "sc750_error.h"
#include "sc750_program.h"

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace drive_core::sc750 {

struct CompileOptions {
    bool turbo = false; // turbo SC750: 25,000 data + 57,216 code bytes; standard: 25,000 in all
};

struct CompileResult {
    std::optional<CompileError> error; // set when the compile failed
    Program program;
    std::vector<std::uint8_t> bin; // the .BIN image
    bool ok() const { return !error.has_value(); }
};

CompileResult compile(std::string_view source, CompileOptions options = {});

} // namespace drive_core::sc750
