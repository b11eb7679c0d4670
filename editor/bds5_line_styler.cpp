// BDS5 line styling: entries are separated by blanks (`;` after a blank starts a comment), a first entry
// ending in `$` is a label, and inside an entry words, numbers, operators and [formats] alternate
// (expressions have no spaces, seed-bds5 §4.3). Words are looked up in the catalog.
#include "bds5_line_styler.h"

#include "drive_core/catalog/bds5_catalog.h"

#include <array>
#include <string>
#include <string_view>

namespace editor {

namespace cat = drive_core::catalog::bds5;

namespace {

bool isBlank(char c) {
    return c == ' ' || c == '\t';
}
bool isEol(char c) {
    return c == '\r' || c == '\n';
}
bool isDigit(char c) {
    return c >= '0' && c <= '9';
}
bool isAlpha(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}
bool isWordChar(char c) {
    return isAlpha(c) || isDigit(c) || c == '_';
}
bool isHexDigit(char c) {
    return isDigit(c) || (c >= 'A' && c <= 'F');
}
bool isOperator(char c) {
    return c == '+' || c == '-' || c == '*' || c == '/' || c == '&' || c == '!' || c == '|' || c == '(' || c == ')' ||
           c == '=' || c == ':';
}

std::string upper(const char* begin, const char* end) {
    std::string out(begin, end);
    for (char& c : out)
        if (c >= 'a' && c <= 'z') c = char(c - 'a' + 'A');
    return out;
}

bool isOneOf(std::string_view word, std::initializer_list<std::string_view> words) {
    for (std::string_view w : words)
        if (w == word) return true;
    return false;
}

// A command that may appear in a program or at the terminal (the editor's own I, F, DEL ... may not).
bool isCommand(std::string_view word) {
    const cat::CommandInfo* c = cat::findCommand(word);
    return c && (c->modes & (cat::kProgram | cat::kInteractive | cat::kMonitor)) != 0;
}

// Decimal, or hex that starts with a decimal digit and ends in H (`0FFH`; `FFH` is no number, L1680-1698).
bool isNumber(const std::string& word) {
    bool allDigits = true;
    for (char c : word) allDigits = allDigits && isDigit(c);
    if (allDigits) return true;
    if (word.size() < 2 || word.back() != 'H') return false;
    for (std::size_t i = 0; i + 1 < word.size(); ++i)
        if (!isHexDigit(word[i])) return false;
    return true;
}

bool isLabelName(const std::string& name) {
    if (name.empty()) return false;
    bool allDigits = true;
    for (char c : name) allDigits = allDigits && isDigit(c);
    return allDigits || isOneOf(name, {"POWER-UP", "AUTO", "MANUAL", "ERROR", "VARIABLE", "BACKGROUND", "A", "B", "C"});
}

struct Styler {
    const QByteArray& line;
    QByteArray styles;
    qsizetype n;
    bool expectCommand = true; // the next entry starts an instruction
    int conditionEntries = 0;  // entries of a ? / TIL condition still to come, then an instruction
    bool freeText = false;     // after >BDS or PASS: a password, not a word to check

    explicit Styler(const QByteArray& l) : line(l), styles(l.size(), char(Bds5Default)), n(l.size()) {}

    void paint(qsizetype from, qsizetype to, Bds5Style style) {
        for (qsizetype k = from; k < to; ++k) styles[k] = char(style);
    }

    Bds5Style classifyWord(const std::string& word, bool wholeEntry, bool atCommand, char next) const {
        if (isDigit(word.front())) return isNumber(word) ? Bds5Number : Bds5Error;
        if (atCommand && wholeEntry && isCommand(word)) return Bds5Command;
        if (isOneOf(word, {"ON", "OFF", "Y", "N"})) return Bds5Constant;
        if (isOneOf(word, {"GT", "GE", "LT", "LE", "EQ", "NE"})) return Bds5Condition;
        if (const auto ref = cat::findVariable(word)) return ref->info->isSwitch ? Bds5Switch : Bds5Variable;
        if (next == '(' && word == "X") return Bds5Variable; // X(X5): indirect addressing
        if (isOneOf(word, {"CW", "CCW", "CAM", "VERSION", "TL", "HIST", "CLR", "START", "STOP", "NEWEST", "OLDEST",
                           "BEG", "END"}))
            return Bds5Keyword;
        if (isCommand(word)) return Bds5Command; // ? X1 GT 0 B : P 1 and the like
        return Bds5Error;
    }

    // One blank-delimited entry [from, to) that is not a quoted string.
    void entry(qsizetype from, qsizetype to) {
        const bool atCommand = expectCommand;
        expectCommand = false;
        const std::string whole = upper(line.constData() + from, line.constData() + to);
        if (freeText) return;
        const bool punctuation = whole == "=" || whole == "$" || whole == ";"; // catalog rows, not commands
        if (atCommand && !punctuation && (whole == "?" || isCommand(whole))) {
            paint(from, to, Bds5Command);
            if (whole == "?" || whole == "TIL") conditionEntries = 3;
            if (whole == ">BDS") freeText = true;
            return;
        }
        if (whole == "?" || whole == ":") { // a nested quick IF, or the false branch
            paint(from, to, Bds5Command);
            if (whole == "?")
                conditionEntries = 3;
            else
                expectCommand = true;
            return;
        }
        qsizetype i = from;
        while (i < to) {
            const char c = line[i];
            if (isWordChar(c)) {
                qsizetype k = i;
                while (k < to && isWordChar(line[k])) ++k;
                const std::string word = upper(line.constData() + i, line.constData() + k);
                const char next = k < to ? line[k] : ' ';
                paint(i, k, classifyWord(word, i == from && k == to, atCommand, next));
                i = k;
            } else if (c == '[') { // a print or input format: [8.2], [H4], [S]
                qsizetype k = i + 1;
                while (k < to && line[k] != ']') ++k;
                paint(i, i + 1, Bds5Operator);
                paint(i + 1, k, Bds5Number);
                if (k < to) paint(k, k + 1, Bds5Operator);
                i = k + 1;
            } else {
                paint(i, i + 1, isOperator(c) ? Bds5Operator : Bds5Error);
                ++i;
            }
        }
    }

    // Counts the entries of a ? or TIL condition: the entry after its third starts an instruction.
    bool enterEntry() {
        if (conditionEntries == 0) return false;
        --conditionEntries;
        return true;
    }
    void leaveEntry(bool inCondition) {
        if (inCondition && conditionEntries == 0) expectCommand = true;
    }

    QByteArray run() {
        qsizetype i = 0;
        while (i < n && isBlank(line[i])) ++i;
        // A label first on its line: 10$, POWER-UP$, or an alarm A$ with its switch and state.
        qsizetype j = i;
        while (j < n && !isBlank(line[j]) && !isEol(line[j])) ++j;
        if (j > i && line[j - 1] == '$' && line[i] != ';') {
            const std::string name = upper(line.constData() + i, line.constData() + j - 1);
            paint(i, j, isLabelName(name) ? Bds5Label : Bds5Error);
            expectCommand = false;
            i = j;
        }
        while (i < n) {
            const char c = line[i];
            if (isBlank(c) || isEol(c)) {
                ++i;
                continue;
            }
            if (c == ';' && (i == 0 || isBlank(line[i - 1]))) {
                qsizetype end = n;
                while (end > i && isEol(line[end - 1])) --end;
                paint(i, end, Bds5Comment);
                break;
            }
            if (c == '"') {
                qsizetype k = i + 1;
                while (k < n && line[k] != '"' && !isEol(line[k])) ++k;
                const qsizetype end = (k < n && line[k] == '"') ? k + 1 : k;
                const bool inCondition = enterEntry();
                paint(i, end, Bds5String);
                expectCommand = false;
                leaveEntry(inCondition);
                i = end;
                continue;
            }
            qsizetype k = i;
            while (k < n && !isBlank(line[k]) && !isEol(line[k]) && line[k] != '"') ++k;
            const bool inCondition = enterEntry();
            entry(i, k);
            leaveEntry(inCondition);
            i = k;
        }
        return styles;
    }
};

} // namespace

QByteArray styleBds5Line(const QByteArray& line) {
    return Styler(line).run();
}

Bds5LineKind bds5LineKind(const QByteArray& line) {
    qsizetype i = 0;
    const qsizetype n = line.size();
    while (i < n && isBlank(line[i])) ++i;
    qsizetype j = i;
    while (j < n && !isBlank(line[j]) && !isEol(line[j])) ++j;
    if (j == i || line[i] == ';') return Bds5LineKind::Plain;
    const std::string first = upper(line.constData() + i, line.constData() + j);
    if (first.back() == '$')
        return isLabelName(first.substr(0, first.size() - 1)) ? Bds5LineKind::Label : Bds5LineKind::Plain;
    if (first == "IF") return Bds5LineKind::If;
    if (first == "ELIF") return Bds5LineKind::Elif;
    if (first == "ELSE") return Bds5LineKind::Else;
    if (first == "ENDIF") return Bds5LineKind::Endif;
    return Bds5LineKind::Plain;
}

} // namespace editor
