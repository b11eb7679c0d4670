// Splits one BDS5 instruction line into entries (L1343-1365, L7400-7412): separators are spaces,
// ';' starts a comment only at the line start or after a space, quoted text is one entry.
#pragma once

#include "bds5_error.h"

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace drive_core::bds5 {

struct Entry {
    std::string text; // upper-cased unless quoted; quoted entries keep their quotes and case
    int column = 0;   // 0-based position in the line
    bool quoted = false;
};

struct LexedLine {
    std::vector<Entry> entries;
    std::string comment; // without the ';'
};

constexpr int kMaxLineLength = 80; // characters per instruction (L3900, L4193)
constexpr int kMaxEntries = 15;    // entries per instruction, command included (L1343-1365)

// Returns the entries, or the drive's error for quote damage (ERR 87, ERR 88).
std::variant<LexedLine, Bds5Error> lexLine(std::string_view line);
// The same into `out`, whose room is reused (the drive lexes every typed line into one buffer); out is
// unspecified after an error.
std::optional<Bds5Error> lexLine(std::string_view line, LexedLine& out);

} // namespace drive_core::bds5
