// BDS5 line lexer: entries, comments and quote rules.
#include "bds5_lexer.h"

#include <algorithm>
#include <cctype>

namespace drive_core::bds5 {

namespace {
bool isBlank(char c) {
    return c == ' ' || c == '\t';
}

std::string upper(std::string_view s) {
    std::string out(s);
    // Case: the manual is silent; the v3 cam listing types lower-case commands (L9550), so commands and
    // variable names are accepted in either case. Quoted text keeps its case.
    std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return char(std::toupper(c)); });
    return out;
}
} // namespace

std::variant<LexedLine, Bds5Error> lexLine(std::string_view line) {
    LexedLine out;
    if (auto error = lexLine(line, out)) return std::move(*error);
    return out;
}

// line := { blank } [ entry { blank+ entry } ] [ blank ';' comment ] | ';' comment
std::optional<Bds5Error> lexLine(std::string_view line, LexedLine& out) {
    out.entries.clear();
    out.comment.clear();
    const int quotes = int(std::count(line.begin(), line.end(), '"'));
    // Room for a word and three parameters in one allocation (every typed line is lexed, issue 20).
    if (const std::size_t first = line.find_first_not_of(" \t"); first != std::string_view::npos && line[first] != ';')
        out.entries.reserve(4);
    std::size_t i = 0;
    while (i < line.size()) {
        if (isBlank(line[i])) {
            ++i;
            continue;
        }
        if (line[i] == ';') { // first character, or preceded by a blank: a comment to the end of the line
            out.comment.assign(line.substr(i + 1));
            break;
        }
        const std::size_t start = i;
        if (line[i] == '"') {
            const std::size_t close = line.find('"', i + 1);
            if (close == std::string_view::npos) return Bds5Error{88, std::string(line.substr(start)), 0};
            i = close + 1;
            // A closing quote must be followed by a blank or the end of the line (L7400-7408).
            if (i < line.size() && !isBlank(line[i])) return Bds5Error{87, std::string(line.substr(start)), 0};
            out.entries.push_back({std::string(line.substr(start, i - start)), int(start), true});
            continue;
        }
        while (i < line.size() && !isBlank(line[i])) {
            // An opening quote must be preceded by a blank: P"BAD" is ERR 87.
            if (line[i] == '"') {
                if (quotes % 2 != 0) return Bds5Error{88, std::string(line.substr(start)), 0};
                const std::size_t end = line.find_first_of(" \t", i);
                return Bds5Error{87, std::string(line.substr(start, end - start)), 0};
            }
            ++i;
        }
        out.entries.push_back({upper(line.substr(start, i - start)), int(start), false});
    }
    return std::nullopt;
}

} // namespace drive_core::bds5
