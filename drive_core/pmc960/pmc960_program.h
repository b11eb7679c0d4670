// The PMC-960 program buffer: one non-volatile text of CR-separated lines holding every routine (5.4, L1398).
// Capacity 1,940 bytes (digest §1, inferred from the EPROM copy limit L982). Label search finds the first
// "@<label>" at the start of a line (B, F, L, P; #C2 if none).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace drive_core::pmc960 {

class Pmc960Program {
public:
    static constexpr std::size_t kCapacity = 1940;

    const std::string& text() const { return m_text; }
    std::size_t size() const { return m_text.size(); }
    void clear() { m_text.clear(); }
    // Replaces the buffer (EPROM copy at power-up); false if it does not fit (the rest is cut off).
    bool assign(std::string_view text);
    std::string& edit() { return m_text; }

    // Offset of the '@' of the first line "@<label>..."; nullopt if there is none.
    std::optional<std::size_t> findLabel(char label) const;

    // A label P can enter and B/F/L can name: 22H ('"') .. 7AH ('z') (L909, L2362).
    static bool validLabel(char c) { return c >= 0x22 && c <= 0x7A; }

    // The EPROM image rule (5.10, L978-989): starts with "@PROGRAM"; copied up to FFH or 1,940 bytes.
    static std::optional<std::string> epromProgram(std::string_view eprom);

private:
    std::string m_text;
};

} // namespace drive_core::pmc960
