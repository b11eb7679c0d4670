// Dep01Screen: the DEP-01 Data Entry Panel's 2 x 40 display, fed the bytes the drive sends: text at the
// cursor, CR to the line start, LF to the next line (the display scrolls), BS back one, and cursor
// addressing — ESC then the character whose code is the address 0..79 (L4333-4341). Pure; no widgets.
#pragma once

#include <QByteArray>
#include <QString>

#include <array>

namespace app {

class Dep01Screen {
public:
    static constexpr int kColumns = 40;
    static constexpr int kRows = 2;

    Dep01Screen() { clear(); }

    void feed(const QByteArray& bytes);
    void clear();
    QString line(int row) const;            // 40 characters, blank-padded
    int cursor() const { return m_cursor; } // 0..79

private:
    void put(char c);
    void newLine();

    std::array<char, kColumns * kRows> m_cells{};
    int m_cursor = 0;
    bool m_addressNext = false; // the previous byte was ESC
};

} // namespace app
