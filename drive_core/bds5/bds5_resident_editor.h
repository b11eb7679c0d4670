// The BDS5 resident editor (ED, §4.3.2 L3466-3720, App. C L6656-6673): line-numbered editing of program
// memory from a dumb terminal, with its own prompts e-> i-> f-> c->. The drive hands it whole lines
// (after its own echo and CR LF) and Esc; the editor answers with the bytes to send, next prompt included.
#pragma once

#include "bds5_lexer.h"
#include "bds5_program.h"

#include <optional>
#include <string>
#include <utility>

namespace drive_core::bds5 {

class Bds5ResidentEditor {
public:
    explicit Bds5ResidentEditor(Bds5Program& program) : m_program(program) {}

    struct Reply {
        std::string output;  // what the drive transmits, ending with the next prompt unless exited
        bool exited = false; // back to interactive mode: the drive sends "-->" itself
    };

    // ED typed at -->: the editor's first prompt.
    Reply enter();
    // One line typed at the current prompt (without its CR), as typed (not upper-cased).
    Reply line(const std::string& text);
    // Esc: leaves insert/find/change/password sub-modes, or the editor itself.
    Reply escape();

    // The prompt currently shown: "e->", "i->", "f->", "c->".
    std::string prompt() const;

    // The current line, 1..lineCount()+1 (lineCount()+1: after the last line, where I appends).
    int currentLine() const { return m_current; }
    // The error code (86, 110) the last reply printed, once: for the drive's error history (ERR HIST).
    std::optional<int> takeError() { return std::exchange(m_error, std::nullopt); }

private:
    enum class Mode { Command, Insert, Find, ChangeWhat, ChangeTo, OldPassword, NewPassword };

    Reply command(const std::string& text);
    Reply print(const LexedLine& cmd);
    Reply nextLine();
    Reply insert(const LexedLine& cmd);
    Reply erase(const LexedLine& cmd);
    Reply insertLine(const std::string& text);
    Reply findAnswer(const std::string& text);
    Reply changeWhatAnswer(const std::string& text);
    Reply changeToAnswer(const std::string& text);
    Reply passwordAnswer(const std::string& text);

    // Back to e->, after `output` (which, when not empty, ends with CR LF).
    Reply toCommand(std::string output = {});
    // A question on its own line followed by the sub-mode's prompt.
    Reply ask(Mode mode, const std::string& question);
    // "BAD ENTRY" and back to e->.
    Reply badEntry() { return toCommand("BAD ENTRY\r\n"); }
    // An error line in the drive's format ("\aERR 110 'I'   ...EDIT PASSWORD"), then e->.
    Reply error(int code, const std::string& entry);
    // "<n> <text>\r\n"
    std::string printed(int number) const;
    // A line-number argument: a number, BEG or END, that names an existing line.
    std::optional<int> lineArgument(const Entry& entry) const;
    // Where F starts looking (see m_findAfterCurrent).
    int findStart() const { return m_current + (m_findAfterCurrent ? 1 : 0); }
    void goTo(int line);
    bool locked() const { return !m_program.password().empty(); }

    Bds5Program& m_program;
    Mode m_mode = Mode::Command;
    int m_current = 1;
    // Where F starts. The manual's example goes P BEG then F EDITOR and finds line 1 (L3577-3594), yet F
    // again finds the *next* EDITOR line and F C F C ... steps through memory (L3607, L3664). Chosen: F
    // starts on the current line, but after F found it or C changed it, on the line after it. P without
    // an argument keeps this; any move (P n, empty line, I, DEL, NEW, ED) clears it.
    bool m_findAfterCurrent = false;
    std::optional<std::string> m_findText; // shared by F and C's CHANGE WHAT (L3626-3636)
    std::optional<std::string> m_changeTo; // C's CHANGE TO WHAT default
    std::string m_changeWhat;              // the CHANGE WHAT answer while CHANGE TO WHAT is asked
    std::optional<int> m_error;            // see takeError()
};

} // namespace drive_core::bds5
