// ServoBASIC Plus lexer: source text to tokens. Case-insensitive names (upper-cased copy kept), dotted
// predefined names, `$` suffixes, `'`/REM comments (and `\`, the manual's L1024 example), `:` separators.
#pragma once

#include "sc750_error.h"

#include <string>
#include <string_view>
#include <vector>

namespace drive_core::sc750 {

enum class TokenKind {
    Name,     // identifier or keyword: letters, digits, `_`, `.`, optional trailing `$`
    Integer,  // 123
    Float,    // 1.5, .2, 1E3
    String,   // "text" (quotes removed)
    Operator, // + - * / ^ = <> < > <= >= ( ) [ ] , ;
    Colon,
    Newline,
    End,
};

struct Token {
    TokenKind kind = TokenKind::End;
    std::string text;  // as written (strings: without quotes)
    std::string upper; // Name: upper case; others: same as text
    double number = 0; // Integer / Float
    int line = 1;
    int column = 1;
};

inline constexpr int kMaxLineLength = 255; // editor limit, L1019
inline constexpr int kMaxNameLength = 39;  // "less than 40 characters", L1052, L1123

class Lexer {
public:
    // Throws CompileFailure on the first lexical error.
    static std::vector<Token> tokenize(std::string_view source);
};

} // namespace drive_core::sc750
