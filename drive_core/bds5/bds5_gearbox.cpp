// The BDS5's electronic gearbox.
#include "bds5_gearbox.h"

#include <cmath>
#include <cstdlib>

namespace drive_core::bds5 {

namespace cat = catalog::bds5;

namespace {
constexpr double kMaxRate_countsPerMs = 2000; // 2 MHz after the ratio (ERR 97, L7449)

struct Refs {
    cat::VariableRef gear, geari, gearo, voff, pext;
};
const Refs& refs() {
    static const Refs r{*cat::findVariable("GEAR"), *cat::findVariable("GEARI"), *cat::findVariable("GEARO"),
                        *cat::findVariable("VOFF"), *cat::findVariable("PEXT")};
    return r;
}

// Division rounding toward minus infinity, so the remainder stays in 0..den-1 whichever way the master turns.
std::int64_t floorDiv(std::int64_t num, std::int64_t den) {
    const std::int64_t q = num / den;
    return (num % den != 0 && ((num < 0) != (den < 0))) ? q - 1 : q;
}
} // namespace

int Bds5Gearbox::step(const Bds5VariableStore& vars) {
    const Refs& r = refs();
    const std::int32_t master = vars.read(r.pext);
    const std::int64_t delta = m_masterLast ? std::int64_t(master) - *m_masterLast : 0;
    m_masterLast = master;
    m_recentSum += delta - m_recent[m_recentAt];
    m_recent[m_recentAt] = delta;
    m_recentAt = (m_recentAt + 1) % m_recent.size();
    m_velocity_cps = 0;
    if (vars.read(r.gear) == 0) return 0;
    const std::int64_t in = vars.read(r.geari);
    const std::int64_t out = std::max<std::int64_t>(1, vars.read(r.gearo));
    m_remainder += delta * in;
    const std::int64_t whole = floorDiv(m_remainder, out);
    m_remainder -= whole * out;
    // VOFF in basic velocity units: 1/65536 count per ms.
    m_offsetFraction += double(vars.read(r.voff)) / 65536;
    const double offsetWhole = std::floor(m_offsetFraction);
    m_offsetFraction -= offsetWhole;
    m_offset_counts += whole + std::int64_t(offsetWhole);
    m_velocity_cps = (double(delta * in) / double(out) + double(vars.read(r.voff)) / 65536) * 1000;
    // The geared rate over the last 16 ms (a slow master's single counts are no 2 MHz burst).
    if (std::abs(double(m_recentSum * in) / double(out)) / double(m_recent.size()) > kMaxRate_countsPerMs) return 97;
    return 0;
}

} // namespace drive_core::bds5
