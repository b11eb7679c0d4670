// ServoBASIC Plus lexer (see sc750_lexer.h).
#include "sc750_lexer.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace drive_core::sc750 {

namespace {

bool isNameStart(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) != 0;
}
bool isNamePart(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '.';
}
bool isDigit(char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

std::string upper(std::string_view s) {
    std::string u(s);
    for (char& c : u) c = char(std::toupper(static_cast<unsigned char>(c)));
    return u;
}

[[noreturn]] void fail(int line, int column, std::string near, std::string message) {
    throw CompileFailure{CompileError{line, column, std::move(near), std::move(message)}};
}

} // namespace

std::vector<Token> Lexer::tokenize(std::string_view src) {
    std::vector<Token> out;
    std::size_t i = 0;
    int line = 1;
    std::size_t lineStart = 0;
    auto push = [&](TokenKind kind, std::size_t begin, std::string text) {
        Token t;
        t.kind = kind;
        t.upper = kind == TokenKind::Name ? upper(text) : text;
        t.text = std::move(text);
        t.line = line;
        t.column = int(begin - lineStart) + 1;
        out.push_back(std::move(t));
        return &out.back();
    };
    auto skipToEol = [&] {
        while (i < src.size() && src[i] != '\n' && src[i] != '\r') ++i;
    };
    while (i < src.size()) {
        const char c = src[i];
        if (c == '\r' || c == '\n') {
            const std::size_t end = i;
            if (int(end - lineStart) > kMaxLineLength)
                fail(line, kMaxLineLength + 1, "", "line longer than 255 characters");
            push(TokenKind::Newline, i, "");
            i += (c == '\r' && i + 1 < src.size() && src[i + 1] == '\n') ? 2 : 1;
            ++line;
            lineStart = i;
            continue;
        }
        if (c == ' ' || c == '\t') {
            ++i;
            continue;
        }
        const std::size_t begin = i;
        if (c == '\'' || c == '\\') { // comment to end of line (`\` as printed in L1024)
            skipToEol();
            continue;
        }
        if (c == '"') {
            ++i;
            while (i < src.size() && src[i] != '"' && src[i] != '\n' && src[i] != '\r') ++i;
            if (i >= src.size() || src[i] != '"')
                fail(line, int(begin - lineStart) + 1, std::string(src.substr(begin, i - begin)),
                     "string has no closing quote");
            push(TokenKind::String, begin, std::string(src.substr(begin + 1, i - begin - 1)));
            ++i;
            continue;
        }
        if (isDigit(c) || (c == '.' && i + 1 < src.size() && isDigit(src[i + 1]))) {
            bool real = false;
            while (i < src.size() && isDigit(src[i])) ++i;
            if (i < src.size() && src[i] == '.') {
                real = true;
                ++i;
                while (i < src.size() && isDigit(src[i])) ++i;
            }
            if (i < src.size() && (src[i] == 'E' || src[i] == 'e')) {
                std::size_t j = i + 1;
                if (j < src.size() && (src[j] == '+' || src[j] == '-')) ++j;
                if (j < src.size() && isDigit(src[j])) {
                    real = true;
                    i = j;
                    while (i < src.size() && isDigit(src[i])) ++i;
                }
            }
            std::string text(src.substr(begin, i - begin));
            const double value = std::strtod(text.c_str(), nullptr);
            if (i < src.size() && isNameStart(src[i]))
                fail(line, int(begin - lineStart) + 1, text + src[i], "a name must begin with a letter");
            if (!real && value > 2147483647.0) real = true; // too big for INTEGER: a FLOAT constant
            Token* t = push(real ? TokenKind::Float : TokenKind::Integer, begin, std::move(text));
            t->number = value;
            continue;
        }
        if (isNameStart(c)) {
            while (i < src.size() && isNamePart(src[i])) ++i;
            if (i < src.size() && src[i] == '$') ++i;
            std::string text(src.substr(begin, i - begin));
            while (text.size() > 1 && text.back() == '.') { // "x." : the dot is not part of the name
                text.pop_back();
                --i;
            }
            if (int(text.size()) > kMaxNameLength)
                fail(line, int(begin - lineStart) + 1, text, "name longer than 39 characters");
            if (upper(text) == "REM") {
                skipToEol();
                continue;
            }
            push(TokenKind::Name, begin, std::move(text));
            continue;
        }
        if (c == ':') {
            push(TokenKind::Colon, begin, ":");
            ++i;
            continue;
        }
        if (c == '<' || c == '>') {
            std::string op(1, c);
            if (i + 1 < src.size() && (src[i + 1] == '=' || (c == '<' && src[i + 1] == '>'))) op += src[i + 1];
            push(TokenKind::Operator, begin, op);
            i += op.size();
            continue;
        }
        static constexpr std::string_view kSingle = "+-*/^=()[],;";
        if (kSingle.find(c) != std::string_view::npos) {
            push(TokenKind::Operator, begin, std::string(1, c));
            ++i;
            continue;
        }
        fail(line, int(begin - lineStart) + 1, std::string(1, c), "unexpected character");
    }
    if (int(i - lineStart) > kMaxLineLength) fail(line, kMaxLineLength + 1, "", "line longer than 255 characters");
    push(TokenKind::Newline, i, "");
    push(TokenKind::End, i, "");
    return out;
}

} // namespace drive_core::sc750
