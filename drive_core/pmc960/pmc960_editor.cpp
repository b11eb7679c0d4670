// The PMC-960 program-mode editor. Decisions (DECISIONS.md): a character typed over a CR is inserted before
// it, so typing never joins lines; spaces are dropped silently (L1412: spaces are not stored); other
// control characters ring the BELL.
#include "pmc960_editor.h"

#include <algorithm>

namespace drive_core::pmc960 {

namespace {
constexpr char kEsc = 0x1B, kTab = 0x09, kCtrlY = 0x19, kBs = 0x08, kDel = 0x7F, kLf = 0x0A, kCtrlK = 0x0B,
               kCtrlV = 0x16, kBell = 0x07;
}

void Pmc960Editor::start(std::size_t cursor) {
    m_cursor = std::min(cursor, m_program.size());
    m_inserting = false;
    m_insert.clear();
}

bool Pmc960Editor::atLineStart() const {
    return m_cursor == 0 || m_program.text()[m_cursor - 1] == '\r';
}

bool Pmc960Editor::write(char c, Reply& reply) {
    std::string& text = m_program.edit();
    if (m_cursor < text.size() && text[m_cursor] != '\r') {
        text[m_cursor++] = c; // overtype
        return true;
    }
    if (text.size() >= Pmc960Program::kCapacity) {
        reply.error = 0xC1;
        reply.done = true;
        return false;
    }
    text.insert(m_cursor++, 1, c);
    return true;
}

bool Pmc960Editor::flushInsert(Reply& reply) {
    std::string& text = m_program.edit();
    if (text.size() + m_insert.size() > Pmc960Program::kCapacity) {
        reply.error = 0xC1;
        reply.done = true;
        return false;
    }
    text.insert(m_cursor, m_insert);
    m_cursor += m_insert.size();
    m_insert.clear();
    return true;
}

Pmc960Editor::Reply Pmc960Editor::feed(char c, bool echo) {
    Reply reply;
    std::string& text = m_program.edit();
    if (m_inserting) {
        if (c == kEsc) { // leave insert without inserting
            m_inserting = false;
            m_insert.clear();
        } else if (c == kCtrlV) {
            m_inserting = false;
            flushInsert(reply);
        } else if (c == ' ') {
        } else if (c == '\r' || (c >= 0x21 && c <= 0x7E)) {
            m_insert += c;
            if (echo) reply.output += c == '\r' ? std::string("\r\n") : std::string(1, c);
            if (m_insert.size() >= kInsertBuffer) flushInsert(reply); // full: write it, keep inserting
        } else {
            reply.output += kBell;
        }
        return reply;
    }
    switch (c) {
    case kEsc: reply.done = true; return reply;
    case kCtrlV: m_inserting = true; return reply;
    case kTab:
    case kCtrlY:
        if (m_cursor < text.size()) {
            if (echo) reply.output += text[m_cursor] == '\r' ? std::string("\r\n") : std::string(1, text[m_cursor]);
            ++m_cursor;
        }
        return reply;
    case kBs:
    case kDel:
        if (m_cursor > 0) {
            --m_cursor;
            if (echo) reply.output += kBs;
        }
        return reply;
    case kLf: {
        const std::size_t cr = text.find('\r', m_cursor);
        m_cursor = cr == std::string::npos ? text.size() : cr + 1;
        if (echo) reply.output += "\r\n";
        return reply;
    }
    case kCtrlK: {
        const std::size_t cr = text.find('\r', m_cursor);
        text.erase(m_cursor, (cr == std::string::npos ? text.size() : cr) - m_cursor);
        return reply;
    }
    case '}':
        if (atLineStart()) { // erase from the cursor to the end and exit (L930, '}' read for the OCR's ')')
            text.erase(m_cursor);
            if (echo) reply.output += '}';
            reply.done = true;
            return reply;
        }
        break;
    case ' ': return reply;
    case '\r':
        if (m_cursor < text.size() && text[m_cursor] == '\r') {
            ++m_cursor;
        } else if (!write('\r', reply)) {
            return reply;
        }
        if (echo) reply.output += "\r\n";
        return reply;
    default: break;
    }
    if (c < 0x21 || c > 0x7E) {
        reply.output += kBell;
        return reply;
    }
    if (write(c, reply) && echo) reply.output += c;
    return reply;
}

} // namespace drive_core::pmc960
