// The BDS5's electronic gearbox.
#include "bds5_gearbox.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace drive_core::bds5 {

namespace cat = catalog::bds5;

namespace {
constexpr double kMaxRate_countsPerMs = 2000; // 2 MHz after the ratio (ERR 97, L7449)

constexpr double kBasicPerCps2 = 0.065536; // basic acceleration: 1/65536 count per ms²

struct Refs {
    Bds5VariableStore::Slot gear, geari, gearo, voff, pext, ramp, pl, acc, dec; // read every millisecond
};
const Refs& refs() {
    const auto f = [](const char* name) { return Bds5VariableStore::slotOf(*cat::findVariable(name)); };
    static const Refs r{f("GEAR"), f("GEARI"), f("GEARO"), f("VOFF"), f("PEXT"),
                        f("RAMP"), f("PL"),    f("ACC"),   f("DEC")};
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
    if (vars.read(r.gear) == 0) {
        // chosen: GEAR OFF with RAMP on (PL off) brings the velocity command down at DEC, as it came up at ACC;
        // a velocity drive whose command is switched away should not stop as hard as the motor can.
        m_velocity_cps = ramp(0, vars);
        return 0;
    }
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
    m_velocity_cps = ramp((double(delta * in) / double(out) + double(vars.read(r.voff)) / 65536) * 1000, vars);
    // The geared rate over the last 16 ms (a slow master's single counts are no 2 MHz burst).
    if (std::abs(double(m_recentSum * in) / double(out)) / double(m_recent.size()) > kMaxRate_countsPerMs) return 97;
    return 0;
}

// RAMP (L3033-3042, L5599): only as a velocity loop (PL off) are the gearbox's velocity steps limited, to ACC
// while the speed grows and DEC while it falls (through zero: DEC down to rest, then ACC). With PL on the
// gearbox is a position command and RAMP does nothing, as the manual's velocity-drive program notes. Only
// the velocity command is slewed: the master's counts still add to PCMD, which PL off does not follow
// (ZPE before PL ON, as after any velocity-loop running).
double Bds5Gearbox::ramp(double target_cps, const Bds5VariableStore& vars) const {
    const Refs& r = refs();
    if (vars.read(r.ramp) == 0 || vars.read(r.pl) != 0) return target_cps;
    constexpr double kPeriod_s = 0.001;
    const double acc = std::max(double(vars.read(r.acc)), 1.0) / kBasicPerCps2 * kPeriod_s;
    const double dec = std::max(double(vars.read(r.dec)), 1.0) / kBasicPerCps2 * kPeriod_s;
    const double v = m_velocity_cps;
    if (target_cps > v) return v < 0 ? std::min(v + dec, std::min(target_cps, 0.0)) : std::min(v + acc, target_cps);
    if (target_cps < v) return v > 0 ? std::max(v - dec, std::max(target_cps, 0.0)) : std::max(v - acc, target_cps);
    return v;
}

} // namespace drive_core::bds5
