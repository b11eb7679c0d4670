// The BDS5 resident editor: commands P, empty line, PASS, I, F, C, DEL, SIZE, NEW (L3466-3720, L6656-6673).
// Transcripts follow the manual's examples; where it is silent the choice is marked "chosen".
#include "bds5_resident_editor.h"

#include <algorithm>
#include <cctype>
#include <charconv>

namespace drive_core::bds5 {

namespace {
constexpr std::string_view kCrLf = "\r\n";
constexpr std::size_t kMaxPasswordChars = 6; // L3518

std::string upper(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::toupper(c)); });
    return s;
}

std::string trimmed(const std::string& s) {
    const auto first = s.find_first_not_of(" \t");
    if (first == std::string::npos) return {};
    return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

// chosen: F and C match without regard to case, like the drive's commands; the replacement keeps its case.
std::size_t findNoCase(const std::string& text, const std::string& what) {
    return upper(text).find(upper(what));
}
} // namespace

Bds5ResidentEditor::Reply Bds5ResidentEditor::enter() {
    // chosen: every ED session starts on line 1 (the program may have been reloaded with >BDS meanwhile).
    goTo(1);
    return toCommand();
}

Bds5ResidentEditor::Reply Bds5ResidentEditor::line(const std::string& text) {
    switch (m_mode) {
    case Mode::Command: return command(text);
    case Mode::Insert: return insertLine(text);
    case Mode::Find: return findAnswer(text);
    case Mode::ChangeWhat: return changeWhatAnswer(text);
    case Mode::ChangeTo: return changeToAnswer(text);
    case Mode::OldPassword:
    case Mode::NewPassword: return passwordAnswer(text);
    }
    return badEntry();
}

// Esc leaves insert mode (L3530, L3551), aborts F and C (L3607, L3664) and PASS (chosen), or leaves the
// editor.
Bds5ResidentEditor::Reply Bds5ResidentEditor::escape() {
    if (m_mode != Mode::Command) {
        m_mode = Mode::Command;
        return {"\r\n" + prompt(), false};
    }
    return {std::string(kCrLf), true};
}

std::string Bds5ResidentEditor::prompt() const {
    switch (m_mode) {
    case Mode::Insert: return "i->";
    case Mode::Find: return "f->";
    case Mode::ChangeWhat:
    case Mode::ChangeTo: return "c->";
    // chosen: the manual lists no password prompt; the question is answered at e->.
    case Mode::Command:
    case Mode::OldPassword:
    case Mode::NewPassword: return "e->";
    }
    return "e->";
}

// command := "" | P [line [line]] | I [line] | DEL [line [line]] | F | C | PASS | SIZE | NEW  [ ";" comment ]
Bds5ResidentEditor::Reply Bds5ResidentEditor::command(const std::string& text) {
    if (text.find_first_not_of(" \t") == std::string::npos) return nextLine();
    const auto lexed = lexLine(text);
    if (!std::holds_alternative<LexedLine>(lexed)) return badEntry();
    const LexedLine& cmd = std::get<LexedLine>(lexed);
    if (cmd.entries.empty()) return toCommand(); // chosen: a comment alone does nothing
    const std::string& word = cmd.entries.front().text;
    if (word == "P") return print(cmd);
    if (word == "I") return insert(cmd);
    if (word == "DEL") return erase(cmd);
    if (cmd.entries.size() > 1) return badEntry(); // the others take no argument
    if (word == "F") return ask(Mode::Find, m_findText ? "FIND WHAT? " + *m_findText + "?" : "FIND WHAT?");
    if (word == "C") {
        if (locked()) return error(110, "C");
        if (m_current > m_program.lineCount()) return badEntry(); // after the last line: nothing to change
        // The manual quotes the default here but not in FIND WHAT? (L3640 vs L3603).
        return ask(Mode::ChangeWhat, m_findText ? "CHANGE WHAT? \"" + *m_findText + "\"?" : "CHANGE WHAT?");
    }
    if (word == "PASS") {
        // chosen: with a password set, PASS first asks for it, so only its owner can lift the protection.
        return locked() ? ask(Mode::OldPassword, "OLD PASSWORD?") : ask(Mode::NewPassword, "NEW PASSWORD?");
    }
    if (word == "SIZE") {
        // "65 % LEFT" (L3696-3705): whole per cent of the ~16,000 characters still free, rounded down.
        const std::size_t left = (kProgramCapacityChars - m_program.sizeChars()) * 100 / kProgramCapacityChars;
        return toCommand(std::to_string(left) + " % LEFT\r\n");
    }
    if (word == "NEW") { // clears program, password and corruption (L3712, L3718-3720); chosen: no confirmation
        m_program.clear();
        m_program.setPassword({});
        m_program.setCorrupt(false);
        goTo(1);
        return toCommand();
    }
    return badEntry();
}

// P prints a line or a range and goes to the last line printed (L3484-3510).
Bds5ResidentEditor::Reply Bds5ResidentEditor::print(const LexedLine& cmd) {
    const std::size_t args = cmd.entries.size() - 1;
    if (args == 0) {
        if (m_current > m_program.lineCount()) return badEntry();
        return toCommand(printed(m_current)); // no move: a following F still starts after a found line
    }
    if (args > 2) return badEntry();
    const auto first = lineArgument(cmd.entries[1]);
    const auto last = args == 2 ? lineArgument(cmd.entries[2]) : first;
    if (!first || !last || *first > *last) return badEntry(); // chosen: a reversed range is a bad entry
    std::string out;
    for (int n = *first; n <= *last; ++n) out += printed(n);
    goTo(*last);
    return toCommand(out);
}

// An empty line goes down one line and prints it (L3512-3514).
Bds5ResidentEditor::Reply Bds5ResidentEditor::nextLine() {
    if (m_current < m_program.lineCount()) {
        goTo(m_current + 1);
        return toCommand(printed(m_current));
    }
    // chosen: past the last line the editor stands after it, silently, so that I appends there.
    goTo(m_program.lineCount() + 1);
    return toCommand();
}

// I [n]: lines typed go in before the current line, or become the new line n (L3528-3570).
Bds5ResidentEditor::Reply Bds5ResidentEditor::insert(const LexedLine& cmd) {
    if (locked()) return error(110, "I"); // chosen: refused as the drive refuses >BDS, ERR 110 EDIT PASSWORD
    if (cmd.entries.size() > 2) return badEntry();
    if (cmd.entries.size() == 2) {
        const int end = m_program.lineCount() + 1;
        // chosen: I with the number one past the last line appends (the manual's own example is I 5).
        const auto at =
            cmd.entries[1].text == std::to_string(end) ? std::optional<int>(end) : lineArgument(cmd.entries[1]);
        if (!at) return badEntry();
        goTo(*at);
    }
    goTo(m_current); // clamps it, in case it stood past a deleted end
    m_mode = Mode::Insert;
    return {prompt(), false};
}

Bds5ResidentEditor::Reply Bds5ResidentEditor::insertLine(const std::string& text) {
    if (text.empty()) return toCommand();                          // an empty line ends insert mode (L3530)
    if (!m_program.insert(m_current, text)) return error(86, "I"); // USER PROGRAM FULL; chosen: leaves I
    ++m_current;                                                   // the next line follows this one (L3570)
    return {prompt(), false};
}

// DEL [a [b]]: deletes the current line, line a, or lines a..b (L3673-3692); the line after becomes current.
Bds5ResidentEditor::Reply Bds5ResidentEditor::erase(const LexedLine& cmd) {
    if (locked()) return error(110, "DEL");
    const std::size_t args = cmd.entries.size() - 1;
    if (args > 2) return badEntry();
    std::optional<int> first = m_current;
    if (args == 0 && m_current > m_program.lineCount()) return badEntry();
    if (args >= 1) first = lineArgument(cmd.entries[1]);
    const auto last = args == 2 ? lineArgument(cmd.entries[2]) : first;
    if (!first || !last || *first > *last) return badEntry();
    m_program.erase(*first, *last);
    goTo(*first);
    return toCommand(); // chosen: DEL prints nothing
}

// F searches downward for a string, prints the line it is in and goes there (L3572-3614).
Bds5ResidentEditor::Reply Bds5ResidentEditor::findAnswer(const std::string& text) {
    if (!text.empty())
        m_findText = text;
    else if (!m_findText)
        return toCommand(); // chosen: nothing to find and no default: F ends quietly
    for (int n = findStart(); n <= m_program.lineCount(); ++n) {
        if (findNoCase(m_program.line(n), *m_findText) == std::string::npos) continue;
        goTo(n);
        m_findAfterCurrent = true;
        return toCommand(printed(n));
    }
    return toCommand("NOT FOUND\r\n");
}

// C, first question: the string to change; it must be on the current line (L3616-3664).
Bds5ResidentEditor::Reply Bds5ResidentEditor::changeWhatAnswer(const std::string& text) {
    if (!text.empty())
        m_findText = text; // chosen: one string serves F and C, as the manual's example shows
    else if (!m_findText)
        return toCommand();
    // chosen: a string not on the current line is reported at once, before CHANGE TO WHAT? is asked.
    if (findNoCase(m_program.line(m_current), *m_findText) == std::string::npos) return toCommand("NOT FOUND\r\n");
    m_changeWhat = *m_findText;
    return ask(Mode::ChangeTo, m_changeTo ? "CHANGE TO WHAT? \"" + *m_changeTo + "\"?" : "CHANGE TO WHAT?");
}

// C, second question: replaces the first occurrence on the current line and prints the line.
Bds5ResidentEditor::Reply Bds5ResidentEditor::changeToAnswer(const std::string& text) {
    // chosen: an empty answer with no default changes the string to nothing (deletes it).
    if (!text.empty() || !m_changeTo) m_changeTo = text;
    std::string changed = m_program.line(m_current);
    changed.replace(findNoCase(changed, m_changeWhat), m_changeWhat.size(), *m_changeTo);
    // chosen: a line longer than an instruction may be (80 characters) is refused, the line unchanged.
    if (int(changed.size()) > kMaxLineLength) return badEntry();
    if (!m_program.replace(m_current, std::move(changed))) return error(86, "C");
    m_findAfterCurrent = true; // F C F C ... steps through memory (L3664)
    return toCommand(printed(m_current));
}

// PASS (L3516-3526): up to six characters; an empty line removes the protection.
Bds5ResidentEditor::Reply Bds5ResidentEditor::passwordAnswer(const std::string& text) {
    // chosen: stored upper-cased and without surrounding blanks, as >BDS compares its upper-cased argument.
    const std::string typed = upper(trimmed(text));
    if (m_mode == Mode::OldPassword) {
        if (typed != m_program.password()) return error(110, "PASS");
        return ask(Mode::NewPassword, "NEW PASSWORD?");
    }
    // chosen: a password >BDS could not be given as one entry (blanks, ';', '"') or too long: BAD ENTRY.
    if (typed.size() > kMaxPasswordChars || typed.find_first_of(" \t;\"") != std::string::npos) return badEntry();
    m_program.setPassword(typed);
    return toCommand();
}

Bds5ResidentEditor::Reply Bds5ResidentEditor::toCommand(std::string output) {
    m_mode = Mode::Command;
    return {std::move(output) + prompt(), false};
}

Bds5ResidentEditor::Reply Bds5ResidentEditor::ask(Mode mode, const std::string& question) {
    m_mode = mode;
    return {question + std::string(kCrLf) + prompt(), false};
}

// chosen: editor errors look like the drive's own after a command: CR LF LF, BEL, "ERR n 'entry'" and the
// message at column 40 (L6036-6100, L9802-9806).
Bds5ResidentEditor::Reply Bds5ResidentEditor::error(int code, const std::string& entry) {
    m_error = code;
    return toCommand("\r\n\n\a" + formatError(Bds5Error{code, entry, 0}) + std::string(kCrLf));
}

// "1 ;TEST LINE FOR LEARNING ABOUT THE EDITOR" (L3558-3562): number, one blank, the line as stored.
std::string Bds5ResidentEditor::printed(int number) const {
    return std::to_string(number) + " " + m_program.line(number) + std::string(kCrLf);
}

std::optional<int> Bds5ResidentEditor::lineArgument(const Entry& entry) const {
    const int count = m_program.lineCount();
    if (count == 0 || entry.quoted) return std::nullopt;
    if (entry.text == "BEG") return 1;
    if (entry.text == "END") return count;
    int n = 0;
    const auto [ptr, ec] = std::from_chars(entry.text.data(), entry.text.data() + entry.text.size(), n);
    if (ec != std::errc{} || ptr != entry.text.data() + entry.text.size() || n < 1 || n > count) return std::nullopt;
    return n;
}

void Bds5ResidentEditor::goTo(int line) {
    m_current = std::clamp(line, 1, m_program.lineCount() + 1);
    m_findAfterCurrent = false;
}

} // namespace drive_core::bds5
