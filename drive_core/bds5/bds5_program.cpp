// BDS5 program memory and label index.
#include "bds5_program.h"

#include <algorithm>
#include <charconv>

namespace drive_core::bds5 {

void Bds5Program::clear() {
    m_lines.clear();
    m_sizeChars = 0;
    invalidate();
}

bool Bds5Program::append(std::string line) {
    if (m_sizeChars + line.size() + 1 > kProgramCapacityChars) return false;
    m_sizeChars += line.size() + 1;
    m_lines.push_back(std::move(line)); // the index extends to it when next asked: no invalidate()
    return true;
}

bool Bds5Program::insert(int beforeLine, std::string line) {
    if (m_sizeChars + line.size() + 1 > kProgramCapacityChars) return false;
    const auto at = std::size_t(std::clamp(beforeLine, 1, lineCount() + 1) - 1);
    m_sizeChars += line.size() + 1;
    m_lines.insert(m_lines.begin() + std::ptrdiff_t(at), std::move(line));
    invalidate();
    return true;
}

bool Bds5Program::replace(int number, std::string line) {
    std::string& old = m_lines.at(std::size_t(number - 1));
    if (m_sizeChars - old.size() + line.size() > kProgramCapacityChars) return false;
    m_sizeChars = m_sizeChars - old.size() + line.size();
    old = std::move(line);
    invalidate();
    return true;
}

void Bds5Program::erase(int first, int last) {
    first = std::max(first, 1);
    last = std::min(last, lineCount());
    for (int n = first; n <= last; ++n) m_sizeChars -= m_lines[std::size_t(n - 1)].size() + 1;
    if (first <= last) m_lines.erase(m_lines.begin() + (first - 1), m_lines.begin() + last);
    invalidate();
}

const LexedLine& Bds5Program::lexed(int number) const {
    index();
    return m_lexed.at(std::size_t(number - 1));
}

std::optional<int> Bds5Program::numericLabel(const LexedLine& line) {
    if (line.entries.empty() || line.entries.front().quoted) return std::nullopt;
    const std::string& word = line.entries.front().text;
    if (word.size() < 2 || word.back() != '$') return std::nullopt;
    int label = -1;
    const auto [ptr, ec] = std::from_chars(word.data(), word.data() + word.size() - 1, label);
    if (ec != std::errc{} || ptr != word.data() + word.size() - 1 || label < 0 || label > kMaxLabel)
        return std::nullopt;
    return label;
}

std::optional<DedicatedLabel> Bds5Program::dedicatedLabel(const LexedLine& line) {
    if (line.entries.empty()) return std::nullopt;
    const std::string& word = line.entries.front().text;
    if (word == "POWER-UP$") return DedicatedLabel::PowerUp;
    if (word == "AUTO$") return DedicatedLabel::Auto;
    if (word == "MANUAL$") return DedicatedLabel::Manual;
    if (word == "ERROR$") return DedicatedLabel::Error;
    if (word == "VARIABLE$") return DedicatedLabel::Variable;
    if (word == "BACKGROUND$") return DedicatedLabel::Background;
    if (word == "A$") return DedicatedLabel::AlarmA;
    if (word == "B$") return DedicatedLabel::AlarmB;
    if (word == "C$") return DedicatedLabel::AlarmC;
    return std::nullopt;
}

void Bds5Program::invalidate() {
    m_indexedLines = 0;
    m_lexed.clear();
    m_labels.clear();
    m_dedicated.clear();
    m_checkError.reset();
    m_errorLabelLine.reset();
}

// Indexes the lines not indexed yet: all of them after a change, only the new ones after appends (a
// >BDS download asks for the index between lines when ^V arrives, so a full pass each time would make
// a download quadratic in its length).
void Bds5Program::index() const {
    for (std::size_t i = m_indexedLines; i < m_lines.size(); ++i) {
        const int number = int(i) + 1;
        auto lexed = lexLine(m_lines[i]);
        if (std::holds_alternative<Bds5Error>(lexed)) {
            m_lexed.push_back({}); // executing it reports the quote error again, with its line
            continue;
        }
        m_lexed.push_back(std::get<LexedLine>(std::move(lexed)));
        const LexedLine& l = m_lexed.back();
        const auto numeric = numericLabel(l);
        const auto dedicated = dedicatedLabel(l);
        if (!numeric && !dedicated) continue;
        if (m_errorLabelLine && !m_checkError) // ERROR$ must be the last label (L7352)
            m_checkError = Bds5Error{74, l.entries.front().text, number};
        if (numeric && !m_labels.emplace(*numeric, number).second && !m_checkError)
            m_checkError = Bds5Error{71, l.entries.front().text, number};
        if (dedicated && !m_dedicated.emplace(*dedicated, number).second && !m_checkError)
            m_checkError = Bds5Error{71, l.entries.front().text, number};
        if (dedicated == DedicatedLabel::Error) m_errorLabelLine = number;
    }
    m_indexedLines = m_lines.size();
}

std::optional<Bds5Error> Bds5Program::check() const {
    index();
    return m_checkError;
}

std::optional<int> Bds5Program::labelLine(int label) const {
    index();
    const auto it = m_labels.find(label);
    if (it == m_labels.end()) return std::nullopt;
    return it->second;
}

std::optional<int> Bds5Program::dedicatedLine(DedicatedLabel which) const {
    index();
    const auto it = m_dedicated.find(which);
    if (it == m_dedicated.end()) return std::nullopt;
    return it->second;
}

std::optional<AlarmLabel> Bds5Program::alarm(DedicatedLabel which) const {
    const auto line = dedicatedLine(which);
    if (!line) return std::nullopt;
    const LexedLine& l = lexed(*line);
    if (l.entries.size() != 3) return std::nullopt;
    return AlarmLabel{*line, l.entries[1].text, l.entries[2].text == "ON"};
}

std::uint16_t Bds5Program::checksum() const {
    std::uint32_t sum = 0;
    std::uint32_t position = 0;
    for (const std::string& line : m_lines) {
        for (const char c : line) sum += std::uint8_t(c) + (position++ & 0xFF);
        sum += '\r' + (position++ & 0xFF);
    }
    return std::uint16_t(sum & 0xFFFF);
}

} // namespace drive_core::bds5
