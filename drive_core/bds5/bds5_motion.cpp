// BDS5 motion commands on the shared profile generator.
#include "bds5_motion.h"

#include "drive_core/catalog/bds5_catalog.h"

#include <cmath>

namespace drive_core::bds5 {

namespace cat = catalog::bds5;

namespace {
constexpr double kBasicPerCountPerSecond = 65.536;   // basic velocity: 1/65536 count per ms (§5.8)
constexpr double kBasicPerCountPerSecond2 = 0.065536; // basic acceleration: 1/65536 count per ms²
constexpr double kMaxRampSeconds = 30;                // an accel or decel segment longer is ERR 32

double basic(const Bds5VariableStore& vars, const char* name) {
    const auto ref = cat::findVariable(name);
    return ref ? double(vars.read(*ref)) : 0.0;
}
} // namespace

double Bds5Motion::rate(const Bds5VariableStore& vars, const char* name) const {
    return std::max(basic(vars, name), 1.0) / kBasicPerCountPerSecond2;
}

int Bds5Motion::checkCanMove(const Bds5VariableStore& vars, bool enabled) const {
    if (!enabled) return 50;                                  // DRIVE INHIBITED
    if (basic(vars, "MOTION") == 0) return 19;                // MOTION (HDWR LINE)
    return 0;
}

int Bds5Motion::jog(const Bds5VariableStore& vars, bool enabled, std::int64_t velocity) {
    if (const int e = checkCanMove(vars, enabled)) return e;
    if (std::llabs(velocity) > std::int64_t(basic(vars, "VMAX"))) return 33; // J: within ±VMAX (L7254)
    const double target = double(velocity) / kBasicPerCountPerSecond;
    const double acc = rate(vars, "ACC");
    const double dec = rate(vars, "DEC");
    if (std::abs(target - m_profile.velocity()) / std::min(acc, dec) > kMaxRampSeconds) return 32;
    if (velocity == 0 && !m_profile.moving()) return 0;
    m_profile.jog({motion::MoveKind::Jog, 0, target, acc, dec});
    return 0;
}

int Bds5Motion::move(const Bds5VariableStore& vars, bool enabled, std::int64_t target,
                     std::optional<std::int64_t> velocity, bool incremental) {
    if (const int e = checkCanMove(vars, enabled)) return e;
    const std::int64_t v = velocity.value_or(std::int64_t(basic(vars, "VDEFAULT")));
    if (v <= 0 || v > std::int64_t(basic(vars, "VMAX"))) return 33; // other moves: 0..+VMAX (L7254)
    const double acc = rate(vars, "ACC");
    const double dec = rate(vars, "DEC");
    const double cps = double(v) / kBasicPerCountPerSecond;
    if (cps / acc > kMaxRampSeconds || cps / dec > kMaxRampSeconds) return 32; // checked before motion
    if (m_profile.jogging()) return 58; // NOT w/JOGGING (L7307)
    if (m_profile.full()) return 30;
    const double end = incremental ? std::round(m_profile.finalPosition()) + double(target) : double(target);
    return m_profile.push({motion::MoveKind::Position, end, cps, acc, dec}) ? 0 : 30;
}

void Bds5Motion::stop(const Bds5VariableStore& vars) { m_profile.stop(rate(vars, "AMAX")); }

void Bds5Motion::halt() { m_profile.stop(1e18); }

int Bds5Motion::normalize(std::int64_t position) {
    if (m_profile.moving()) return 57;
    m_profile.setPosition(double(position));
    return 0;
}

void Bds5Motion::step(Microseconds dt, Bds5VariableStore& vars) {
    m_profile.step(double(dt.count()) / 1e6);
    const auto position = std::int32_t(std::llround(m_profile.position()));
    const auto velocity = std::int32_t(std::llround(m_profile.velocity() * kBasicPerCountPerSecond));
    vars.set("PCMD", position);
    vars.set("PFB", position);
    vars.set("PE", 0);
    vars.set("VCMD", velocity);
    vars.set("VFB", velocity);
    vars.set("SEG", m_profile.segment());
    vars.set("PFNL", std::int32_t(std::llround(m_profile.finalPosition())));
}

} // namespace drive_core::bds5
