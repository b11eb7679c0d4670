// Dep01Screen: the DEP-01's byte handling.
#include "dep01_screen.h"

namespace app {

namespace {
constexpr char kEsc = '\x1b';
constexpr char kBell = '\a';
} // namespace

void Dep01Screen::clear() {
    m_cells.fill(' ');
    m_cursor = 0;
    m_addressNext = false;
}

QString Dep01Screen::line(int row) const {
    if (row < 0 || row >= kRows) return {};
    return QString::fromLatin1(m_cells.data() + row * kColumns, kColumns);
}

void Dep01Screen::newLine() {
    if (m_cursor / kColumns + 1 < kRows) {
        m_cursor = (m_cursor / kColumns + 1) * kColumns + m_cursor % kColumns;
        return;
    }
    // On the last line: scroll up one line, the cursor stays in its column.
    std::copy(m_cells.begin() + kColumns, m_cells.end(), m_cells.begin());
    std::fill(m_cells.end() - kColumns, m_cells.end(), ' ');
    if (m_cursor >= kColumns * kRows) m_cursor = (kRows - 1) * kColumns;
}

void Dep01Screen::put(char c) {
    if (m_cursor >= kColumns * kRows) newLine(); // past the last cell: scroll, go on at the last line
    m_cells[std::size_t(m_cursor++)] = c;
}

void Dep01Screen::feed(const QByteArray& bytes) {
    for (const char c : bytes) {
        if (m_addressNext) {
            m_addressNext = false;
            const int address = static_cast<unsigned char>(c);
            if (address < kColumns * kRows) {
                m_cursor = address;
                continue;
            }
        }
        switch (c) {
        case kEsc: m_addressNext = true; break;
        case '\r': // just past the last cell the cursor is still on the last line
            m_cursor = m_cursor >= kColumns * kRows ? (kRows - 1) * kColumns : m_cursor - m_cursor % kColumns;
            break;
        case '\n': newLine(); break;
        case '\b': m_cursor = m_cursor > 0 ? m_cursor - 1 : 0; break;
        case kBell: break;
        default:
            if (static_cast<unsigned char>(c) >= ' ' && static_cast<unsigned char>(c) < 0x7f) put(c);
        }
    }
}

} // namespace app
