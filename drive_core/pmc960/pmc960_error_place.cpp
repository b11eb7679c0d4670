// Placing a program error: from SB&'s label and count to the command, by the interpreter's counting rules
// (pmc960_interpreter.cpp finish(), pmc960_flow.cpp): a finished command counts, a label line passed sets the
// count to 0, B F L count before they jump, an E that returns and a Q that ends count nothing.
#include "pmc960_error_place.h"

#include <algorithm>
#include <cctype>

namespace drive_core::pmc960 {

namespace {

constexpr int kLabelUndefined = 0xC2;

bool isLabelLine(const std::string& line) {
    return !line.empty() && line[0] == '@';
}

// "@" alone is no label: the interpreter reads the CR as the end of an empty label line.
char labelOf(const std::string& line) {
    return isLabelLine(line) && line.size() >= 2 ? line[1] : 0;
}

char upper(char c) {
    return char(std::toupper(static_cast<unsigned char>(c)));
}

bool hasHexDigit(std::string_view text) {
    return std::any_of(text.begin(), text.end(), [](char c) { return std::isxdigit(static_cast<unsigned char>(c)); });
}

// How straight execution goes on after a command that finished.
enum class Flow { Next, Return, Leaves };

// A condition (<hex>[:<mask>]) may stop B F E Q from acting; without one they always do (L1075-1163).
Flow flowOf(const std::string& command) {
    switch (upper(command[0])) {
    case 'E': return hasHexDigit(std::string_view(command).substr(1)) ? Flow::Next : Flow::Return;
    case 'Q': return hasHexDigit(std::string_view(command).substr(1)) ? Flow::Next : Flow::Leaves;
    case 'B': // jumps: the label it reaches is the one SB names
    case 'F': // calls: the same for the callee's label
        return command.size() > 2 && hasHexDigit(std::string_view(command).substr(2)) ? Flow::Next : Flow::Leaves;
    default: return Flow::Next; // L loops back to a label (which SB then names) or falls through
    }
}

// The routine a line belongs to: the nearest label line above it whose label is not '.' (a comment line).
char routineAt(const std::vector<std::string>& lines, std::size_t at) {
    for (std::size_t i = at + 1; i-- > 0;) {
        const char label = labelOf(lines[i]);
        if (label != 0 && label != '.') return label;
    }
    return 0;
}

// The one line whose command calls routine (F<routine>...), if exactly one does.
std::optional<std::size_t> onlyCaller(const std::vector<std::string>& lines, char routine) {
    std::optional<std::size_t> caller;
    for (std::size_t i = 0; i < lines.size() && routine != 0; ++i) {
        const auto commands = commandsOf(lines[i]);
        if (commands.empty() || upper(commands[0][0]) != 'F' || commands[0].size() < 2 || commands[0][1] != routine)
            continue;
        if (caller) return std::nullopt;
        caller = i;
    }
    return caller;
}

} // namespace

std::vector<std::string> commandsOf(std::string_view line) {
    std::vector<std::string> commands;
    if (line.empty() || line[0] == '@') return commands;
    std::string current;
    auto close = [&] {
        if (current.find_first_not_of(". ") != std::string::npos) commands.push_back(current); // fillers (L926)
        current.clear();
    };
    for (const char c : line) {
        current += c;
        if (c == '?' || c == '!' || c == '&') close();
    }
    close();
    return commands;
}

std::optional<Pmc960ErrorPlace> placeProgramError(const std::vector<std::string>& lines, char started, char lastLabel,
                                                  int commandsSince, int code) {
    // B, F and L count themselves before they jump (pmc960_flow.cpp): one whose label is missing (#C2) is one
    // before the count.
    const int target = code == kLabelUndefined ? commandsSince - 1 : commandsSince;
    if (target < 0) return std::nullopt;
    // The label line: execution falls through labels in text order, so the first @<label> at or after the
    // routine started; else the first in the buffer, where B, F and L jump (the label search, L1026-1057).
    std::vector<std::size_t> candidates;
    std::optional<std::size_t> startLine;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const char label = labelOf(lines[i]);
        if (label == lastLabel && label != 0) candidates.push_back(i);
        if (label == started && label != 0 && !startLine) startLine = i;
    }
    if (candidates.empty()) return std::nullopt;
    std::size_t from = candidates.front();
    if (startLine) {
        const auto after =
            std::find_if(candidates.begin(), candidates.end(), [&](std::size_t i) { return i >= *startLine; });
        if (after != candidates.end()) from = *after;
    }
    Pmc960ErrorPlace place;
    place.ambiguous = candidates.size() > 1;
    int index = 0;
    std::size_t steps = 0; // each return moves to a caller: a recursive program must not walk for ever
    for (std::size_t at = from + 1; at < lines.size() && steps <= lines.size() * 2; ++at, ++steps) {
        if (isLabelLine(lines[at])) {
            if (labelOf(lines[at]) == 0) continue;
            return std::nullopt; // passing it would have set the count to 0 and SB to its label
        }
        for (const std::string& command : commandsOf(lines[at])) {
            const Flow flow = flowOf(command);
            // An unconditional E without a sync cannot fail: at the count, the failing command follows the return.
            const bool returns = flow == Flow::Return && command.find_first_of(",;") == std::string::npos;
            if (index == target && !returns) {
                place.line = at;
                place.command = command;
                place.routine = routineAt(lines, at);
                return place;
            }
            if (flow == Flow::Leaves) return std::nullopt;
            if (flow == Flow::Return) {
                // E returns without counting: the count goes on after the F that called this routine.
                const auto caller = onlyCaller(lines, routineAt(lines, at));
                if (!caller) return std::nullopt;
                place.afterReturn = true;
                at = *caller; // the loop steps to the line after it
                break;
            }
            ++index;
        }
    }
    return std::nullopt;
}

} // namespace drive_core::pmc960
