// BDS5 profile regulation: the profile clock from the external input.
#include "bds5_regulation.h"

#include "drive_core/catalog/bds5_catalog.h"

#include <algorithm>

namespace drive_core::bds5 {

namespace {
constexpr std::int64_t kMaxBackward_counts = 30000; // ERR 64 beyond (L7334)

struct Refs {
    Bds5VariableStore::Slot reg, regkhz, pext; // read every millisecond
};
const Refs& refs() {
    const auto f = [](const char* name) { return Bds5VariableStore::slotOf(*catalog::bds5::findVariable(name)); };
    static const Refs r{f("REG"), f("REGKHZ"), f("PEXT")};
    return r;
}
} // namespace

Bds5Regulation::Tick Bds5Regulation::step(const Bds5VariableStore& vars, double dt_ms) {
    const Refs& r = refs();
    const std::int32_t pext = vars.read(r.pext);
    const std::int64_t delta = m_lastPext ? std::int64_t(pext) - *m_lastPext : 0;
    m_lastPext = pext;
    if (vars.read(r.reg) == 0) {
        m_backward_counts = 0;
        return {};
    }
    // Backward counts halt the profile; forward counts first cancel them, then drive it again.
    std::int64_t forward = delta;
    if (m_backward_counts > 0 || delta < 0) {
        m_backward_counts -= delta;
        forward = m_backward_counts < 0 ? -m_backward_counts : 0;
        m_backward_counts = std::max<std::int64_t>(m_backward_counts, 0);
    }
    if (m_backward_counts > kMaxBackward_counts) {
        m_backward_counts = 0;
        return {0, 64};
    }
    // REGKHZ kHz is REGKHZ counts per ms: that rate runs the profile as specified (L3059-3075).
    const double full = double(std::max(vars.read(r.regkhz), 1)) * dt_ms;
    return {std::min(1.0, double(forward) / full), 0};
}

} // namespace drive_core::bds5
