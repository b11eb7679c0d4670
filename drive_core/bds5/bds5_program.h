// The BDS5 user program memory: lines of text in battery-backed RAM (~16,000 characters, L3696-3706),
// their labels, and the checks RUN makes before it starts (ERR 71, 74). Line numbers count from 1.
#pragma once

#include "bds5_error.h"
#include "bds5_lexer.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace drive_core::bds5 {

constexpr std::size_t kProgramCapacityChars = 16000; // L3696-3706 ("65 % LEFT" of ~16,000 characters)
constexpr int kMaxLabel = 500;                       // general-purpose labels 0..500 (L3728-3747)

// Dedicated labels (Table 4.5): the main-level ones run in task level 5, the others have their own tasks.
enum class DedicatedLabel { PowerUp, Auto, Manual, Error, Variable, Background, AlarmA, AlarmB, AlarmC };

struct AlarmLabel {
    int line = 0;
    std::string switchName; // "I1", "XS3", "MANUAL"
    bool on = true;         // fires on the switch turning ON (positive edge) or OFF
};

class Bds5Program {
public:
    void clear();
    // Appends one line as received by >BDS or typed in the editor's insert mode. False (ERR 86) when
    // the memory is full; the line is then not stored.
    bool append(std::string line);
    // The resident editor's changes (lines count from 1). False (ERR 86) when memory would overflow.
    bool insert(int beforeLine, std::string line);
    bool replace(int number, std::string line);
    void erase(int first, int last);
    // The editor password (PASS, up to six characters; empty = none). NEW clears it; >BDS keeps it.
    const std::string& password() const { return m_password; }
    void setPassword(std::string password) { m_password = std::move(password); }
    // "USER PROGRAM CORRUPT" (ERR 202): power was lost while the program was being changed. RUN refuses the
    // program until NEW or >BDS clears it (L3712, L3746, L7513).
    bool corrupt() const { return m_corrupt; }
    void setCorrupt(bool corrupt) { m_corrupt = corrupt; }

    std::size_t sizeChars() const { return m_sizeChars; }
    int lineCount() const { return int(m_lines.size()); }
    const std::string& line(int number) const { return m_lines.at(std::size_t(number - 1)); }
    const LexedLine& lexed(int number) const;
    const std::vector<std::string>& lines() const { return m_lines; }

    // The checks RUN makes (labels used twice, labels after ERROR$); the first error with its line.
    std::optional<Bds5Error> check() const;
    std::optional<int> labelLine(int label) const; // line of "n$"
    std::optional<int> dedicatedLine(DedicatedLabel which) const;
    std::optional<AlarmLabel> alarm(DedicatedLabel which) const; // A$, B$, C$

    // P CHECKSUM (L9953-9984): "a special word checksum of the internal program memory with a varying
    // offset" the host cannot recompute. Chosen: the 16-bit sum of every stored byte (lines with their CR)
    // each plus its position modulo 256, so any changed, moved, added or missing character changes it.
    std::uint16_t checksum() const;

    // What a line is, for the executor and RUN's checks: "10$" -> label 10; "POWER-UP$" -> dedicated.
    static std::optional<int> numericLabel(const LexedLine& line);
    static std::optional<DedicatedLabel> dedicatedLabel(const LexedLine& line);

private:
    void index() const;
    void invalidate(); // after any change but an append

    std::vector<std::string> m_lines;
    std::size_t m_sizeChars = 0;
    std::string m_password;
    bool m_corrupt = false;
    // Derived on demand: lines [0, m_indexedLines) are indexed.
    mutable std::size_t m_indexedLines = 0;
    mutable std::vector<LexedLine> m_lexed;
    mutable std::map<int, int> m_labels;
    mutable std::map<DedicatedLabel, int> m_dedicated;
    mutable std::optional<Bds5Error> m_checkError;
    mutable std::optional<int> m_errorLabelLine; // ERROR$, once seen: any label after it is ERR 74
};

} // namespace drive_core::bds5
