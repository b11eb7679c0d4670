// BDS5 camming: PCMD modulo one cam cycle, and PCAM interpolated from X100-X227.
#include "bds5_cam.h"

#include "drive_core/catalog/bds5_catalog.h"

#include <cmath>

namespace drive_core::bds5 {

namespace {
std::int64_t wrap(std::int64_t counts) {
    return ((counts % kCamCycle_counts) + kCamCycle_counts) % kCamCycle_counts;
}
} // namespace

double Bds5Cam::lookup(std::int64_t pcmd_counts, const Bds5VariableStore& vars) {
    static const catalog::bds5::VariableRef first = *catalog::bds5::findVariable("X100");
    const std::int64_t p = wrap(pcmd_counts);
    const int i = int(p / 256), f = int(p % 256);
    catalog::bds5::VariableRef a = first, b = first;
    a.index = kCamFirstRegister + i;
    b.index = kCamFirstRegister + (i + 1) % kCamPoints;
    const double x0 = vars.read(a), x1 = vars.read(b);
    return x0 + (x1 - x0) * f / 256;
}

void Bds5Cam::start(std::int64_t master_counts, double command_counts, const Bds5VariableStore& vars) {
    m_on = true;
    m_origin_counts = double(wrap(master_counts)) - std::round(command_counts);
    m_pcmd = wrap(master_counts);
    m_pcam = lookup(m_pcmd, vars);
    m_pcamVelocity_cps = 0;
}

void Bds5Cam::step(double command_counts, const Bds5VariableStore& vars, double period_s) {
    if (!m_on) return;
    m_pcmd = wrap(std::llround(command_counts + m_origin_counts));
    const double pcam = lookup(m_pcmd, vars);
    m_pcamVelocity_cps = (pcam - m_pcam) / period_s;
    m_pcam = pcam;
}

} // namespace drive_core::bds5
