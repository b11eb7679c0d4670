// The BDS5's variable memory: one value per catalog variable (and per index of indexed families),
// initialised from the catalog's power-up values. Values are kept in basic units.
#pragma once

#include "drive_core/catalog/bds5_catalog.h"

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace drive_core::bds5 {

class Bds5VariableStore {
public:
    Bds5VariableStore();

    // Power-up: volatile variables take their power-up values; remembered ones keep theirs.
    void powerUp();

    std::optional<std::int32_t> read(std::string_view upperName) const;
    std::int32_t read(const catalog::bds5::VariableRef& ref) const;

    // The drive's checks for a write from the terminal or a program: 0 if accepted, else the error
    // number (80 unknown, 81 monitor variable, 111 factory, 51 needs disabled, 83 out of range).
    int write(std::string_view upperName, std::int64_t value, bool driveEnabled);

    // Unchecked write, for the drive's own bookkeeping (monitor variables it maintains).
    void set(const catalog::bds5::VariableRef& ref, std::int32_t value);
    void set(std::string_view upperName, std::int32_t value);

private:
    // IN and OUT are the words of the I1-I16 and O1-O8 switches (I1 = bit 0): one memory, two views.
    std::optional<std::int32_t> word(const catalog::bds5::VariableRef& ref) const;
    void setBits(std::string_view stem, int count, std::int32_t word);
    std::size_t slot(const catalog::bds5::VariableRef& ref) const;

    std::vector<std::size_t> m_firstSlot; // per catalog entry, its first slot in m_values
    std::vector<std::int32_t> m_values;
};

} // namespace drive_core::bds5
