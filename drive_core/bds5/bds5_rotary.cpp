// The BDS5's rotary roll-over, exact in user units.
#include "bds5_rotary.h"

#include <algorithm>

namespace drive_core::bds5 {

namespace cat = catalog::bds5;

namespace {
struct Refs {
    Bds5VariableStore::Slot rotary, protary, pnum, pden; // read every millisecond
};
const Refs& refs() {
    const auto f = [](const char* name) { return Bds5VariableStore::slotOf(*cat::findVariable(name)); };
    static const Refs r{f("ROTARY"), f("PROTARY"), f("PNUM"), f("PDEN")};
    return r;
}

std::int64_t floorDiv(std::int64_t num, std::int64_t den) {
    const std::int64_t q = num / den;
    return (num % den != 0 && ((num < 0) != (den < 0))) ? q - 1 : q;
}
} // namespace

std::int64_t Bds5Rotary::rollover(std::int64_t pfb_counts, const Bds5VariableStore& vars) {
    const Refs& r = refs();
    if (vars.read(r.rotary) == 0) return 0;
    const std::int64_t pnum = std::max<std::int32_t>(vars.read(r.pnum), 1);
    const std::int64_t pden = std::max<std::int32_t>(vars.read(r.pden), 1);
    // PROTARY as the user typed it: the store keeps it in counts, rounded; user units give it back exactly
    // (PROTARY cannot change while ROTARY is on, so neither can this).
    const std::int64_t protary = vars.toUser(cat::UnitClass::Position, vars.read(r.protary)).value_or(0);
    if (protary <= 0) return 0; // chosen: no roll-over distance, no roll-over (ROTARY ON refuses PFB > 0 anyway)
    const std::int64_t pfb = vars.toUser(cat::UnitClass::Position, pfb_counts).value_or(0);
    // "If PFB is greater than PROTARY ... if PFB is less than zero" (L5256): PFB = PROTARY stays as it is.
    int direction = 0;
    if (pfb > protary)
        direction = -1;
    else if (pfb < 0)
        direction = 1;
    if (direction == 0) return 0;
    // PROTARY in counts is protary * PNUM / PDEN; the part below a count is carried in m_remainder.
    const std::int64_t exact = direction * protary * pnum + m_remainder;
    const std::int64_t whole = floorDiv(exact, pden);
    m_remainder = exact - whole * pden;
    return whole;
}

} // namespace drive_core::bds5
