// The PMC-960 parameter table: stored (?) and in-use (!) values.
#include "pmc960_table.h"

namespace drive_core::pmc960 {

namespace catalog = drive_core::catalog::pmc960;

Pmc960Table::Pmc960Table() {
    for (const auto& p : catalog::parameters())
        if (p.nonVolatile) m_stored[std::string(p.name)] = p.factory;
    m_inUse = m_stored;
}

void Pmc960Table::load(bool generic) {
    m_inUse = m_stored;
    if (!generic) return;
    for (const auto& p : catalog::parameters())
        if (p.nonVolatile) m_inUse[std::string(p.name)] = p.generic;
}

std::int64_t Pmc960Table::stored(std::string_view name) const {
    const auto it = m_stored.find(name);
    return it == m_stored.end() ? 0 : it->second;
}

std::int64_t Pmc960Table::inUse(std::string_view name) const {
    const auto it = m_inUse.find(name);
    return it == m_inUse.end() ? 0 : it->second;
}

void Pmc960Table::set(std::string_view name, std::int64_t value) {
    const auto it = m_stored.find(name);
    if (it == m_stored.end()) return;
    it->second = value;
    m_inUse[std::string(name)] = value;
}

Pmc960Table::FeedForward Pmc960Table::feedForward() const {
    const int g = int(stored("TGF"));
    return {g / 4, g, g * 2 > 255 ? 255 : g * 2, g};
}

} // namespace drive_core::pmc960
