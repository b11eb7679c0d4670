// The BDS5's variable memory: one value per catalog variable (and per index of indexed families),
// initialised from the catalog's power-up values. Values are kept in basic units; reads and writes by
// name are in user units, through the NUM/DEN pair of the variable's unit class (L5027-5246).
#pragma once

#include "drive_core/catalog/bds5_catalog.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

// The servo tick's hot accessors carry no fuzzing coverage callbacks: they run a score of times every
// simulated millisecond, and the fuzz build (tests/fuzz) keeps the tick itself uninstrumented too.
#if defined(__clang__)
#define SERVODESK_NO_COVERAGE __attribute__((no_sanitize("coverage")))
#else
#define SERVODESK_NO_COVERAGE
#endif

namespace drive_core::bds5 {

class Bds5VariableStore {
public:
    Bds5VariableStore();

    // Power-up: volatile variables take their power-up values; remembered ones keep theirs.
    void powerUp();

    // Whether the drive has the variable now: every catalog variable does, but the extended indices of a
    // family only while its switch is on (v3: X251-X750 while EXTDX is on, L9309).
    bool exists(const catalog::bds5::VariableRef& ref) const;
    bool exists(std::string_view upperName) const;

    // In user units; nullopt if there is no such variable (or it does not exist now). A value that overflows
    // 32 bits in user units reads as the nearest 32-bit value (ERR 96 is a write's error).
    std::optional<std::int32_t> read(std::string_view upperName) const;
    // In basic units. Inline: the servo loop reads a score of variables every millisecond.
    SERVODESK_NO_COVERAGE std::int32_t read(const catalog::bds5::VariableRef& ref) const {
        if (ref.info == m_inWord || ref.info == m_outWord) return *word(ref);
        return m_values[slot(ref)];
    }
    // In user units, for code that resolved the name once (it runs every millisecond).
    std::int32_t readUser(const catalog::bds5::VariableRef& ref) const;

    // The drive's checks for a write (in user units) from the terminal or a program: 0 if accepted, else
    // the error number (80 unknown or not existing now, 81 monitor variable, 111 factory, 51 needs disabled,
    // 83 out of range, 96 scaling overflow).
    int write(std::string_view upperName, std::int64_t value, bool driveEnabled);

    // User <-> basic for a unit class: basic = user * NUM / DEN, rounded to nearest (halves away from
    // zero — the manual is silent). nullopt on overflow or a zero denominator.
    std::optional<std::int64_t> toBasic(catalog::bds5::UnitClass unit, std::int64_t user) const;
    std::optional<std::int64_t> toUser(catalog::bds5::UnitClass unit, std::int64_t basic) const;

    // A plain variable's place in the value memory, resolved once for code that reads and writes it every
    // millisecond (the servo tick): no name, no catalog arithmetic, no IN/OUT word. The layout is the same
    // for every drive, so a Slot found once serves all. Invalid for IN and OUT and for a ref without info.
    struct Slot {
        std::size_t at = SIZE_MAX;
        bool valid() const { return at != SIZE_MAX; }
    };
    static Slot slotOf(const catalog::bds5::VariableRef& ref);
    // In basic units, as read(ref) and set(ref, value); the slot must be valid.
    SERVODESK_NO_COVERAGE std::int32_t read(Slot s) const { return m_values[s.at]; }
    SERVODESK_NO_COVERAGE void set(Slot s, std::int32_t value) { m_values[s.at] = value; }

    // Unchecked write, for the drive's own bookkeeping (monitor variables it maintains, CLEARX, EXTDX).
    SERVODESK_NO_COVERAGE void set(const catalog::bds5::VariableRef& ref, std::int32_t value) {
        if (ref.info == m_inWord || ref.info == m_outWord) return setWord(ref, value);
        m_values[slot(ref)] = value;
    }
    void set(std::string_view upperName, std::int32_t value);

private:
    // IN and OUT are the words of the I1-I16 and O1-O8 switches (I1 = bit 0): one memory, two views.
    std::optional<std::int32_t> word(const catalog::bds5::VariableRef& ref) const;
    void setBits(std::string_view stem, int count, std::int32_t word);
    void setWord(const catalog::bds5::VariableRef& ref, std::int32_t value);
    // A plain variable's index is 0, so one table gives both: its slot, or a family's slot less its first index.
    SERVODESK_NO_COVERAGE std::size_t slot(const catalog::bds5::VariableRef& ref) const {
        return std::size_t(m_slotBase[std::size_t(ref.info - m_base)] + ref.index);
    }

    const catalog::bds5::VariableInfo* m_base = nullptr;   // the catalog's first entry
    const catalog::bds5::VariableInfo* m_inWord = nullptr; // IN and OUT: words of bits, not slots
    const catalog::bds5::VariableInfo* m_outWord = nullptr;
    const std::ptrdiff_t* m_slotBase = nullptr; // per catalog entry: slot - index (shared, see layout())
    std::vector<std::int32_t> m_values;
};

} // namespace drive_core::bds5
