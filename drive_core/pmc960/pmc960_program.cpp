// The PMC-960 program buffer.
#include "pmc960_program.h"

namespace drive_core::pmc960 {

bool Pmc960Program::assign(std::string_view text) {
    m_text = std::string(text.substr(0, kCapacity));
    return text.size() <= kCapacity;
}

std::optional<std::size_t> Pmc960Program::findLabel(char label) const {
    for (std::size_t i = 0; i + 1 < m_text.size(); ++i) {
        const bool lineStart = i == 0 || m_text[i - 1] == '\r';
        if (lineStart && m_text[i] == '@' && m_text[i + 1] == label) return i;
    }
    return std::nullopt;
}

std::optional<std::string> Pmc960Program::epromProgram(std::string_view eprom) {
    if (eprom.substr(0, 8) != "@PROGRAM") return std::nullopt;
    const std::size_t end = eprom.find('\xFF');
    std::string_view image = eprom.substr(0, end);
    return std::string(image.substr(0, kCapacity));
}

} // namespace drive_core::pmc960
