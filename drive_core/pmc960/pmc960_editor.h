// The PMC-960 program-mode editor (P command, 5.8 L921-930, 7.15 L1398-1439): an overtype editor working
// directly on the program buffer, with Ctrl-V insert (40-character buffer), Ctrl-K, TAB/Ctrl-Y, BS/DEL, LF,
// '}' in column 1 to erase to the end, and ESC to leave.
#pragma once

#include "pmc960_program.h"

#include <string>

namespace drive_core::pmc960 {

class Pmc960Editor {
public:
    explicit Pmc960Editor(Pmc960Program& program) : m_program(program) {}

    struct Reply {
        std::string output; // echo, BELL (07H)
        bool done = false;  // the editor has ended (ESC, '}' erase, or an error)
        int error = 0;      // #C1 buffer full
    };

    void start(std::size_t cursor);
    Reply feed(char c, bool echo);
    std::size_t cursor() const { return m_cursor; }
    bool inserting() const { return m_inserting; }

    static constexpr std::size_t kInsertBuffer = 40;

private:
    bool atLineStart() const;
    bool write(char c, Reply& reply);
    bool flushInsert(Reply& reply);

    Pmc960Program& m_program;
    std::size_t m_cursor = 0;
    bool m_inserting = false;
    std::string m_insert;
};

} // namespace drive_core::pmc960
