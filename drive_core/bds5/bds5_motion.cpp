// BDS5 motion commands on the shared profile generator.
#include "bds5_motion.h"

#include "drive_core/catalog/bds5_catalog.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace drive_core::bds5 {

namespace cat = catalog::bds5;

namespace {
constexpr double kBasicPerCountPerSecond = 65.536;    // basic velocity: 1/65536 count per ms (§5.8)
constexpr double kBasicPerCountPerSecond2 = 0.065536; // basic acceleration: 1/65536 count per ms²
constexpr double kMaxRampSeconds = 30;                // an accel or decel segment longer is ERR 32

double basic(const Bds5VariableStore& vars, const char* name) {
    const auto ref = cat::findVariable(name);
    return ref ? double(vars.read(*ref)) : 0.0;
}

// The variables step() reads and writes every millisecond, resolved once. step() and writeVariables() are
// part of the servo tick, which the fuzz build leaves without coverage callbacks (tests/fuzz).
struct StepRefs {
    Bds5VariableStore::Slot gate, gatemode, plim, pfb, pmax, pmin, pcam, pcmd, vcmd, seg, pfnl, cam;
};
SERVODESK_NO_COVERAGE const StepRefs& stepRefs() {
    const auto f = [](const char* name) { return Bds5VariableStore::slotOf(*cat::findVariable(name)); };
    static const StepRefs r{f("GATE"), f("GATEMODE"), f("PLIM"), f("PFB"), f("PMAX"), f("PMIN"),
                            f("PCAM"), f("PCMD"),     f("VCMD"), f("SEG"), f("PFNL"), f("CAM")};
    return r;
}

// SCRV (Table 3.7): the shape of every accel and decel segment of the next command.
motion::SCurve shape(const Bds5VariableStore& vars) {
    return motion::sCurveFromLevel(int(basic(vars, "SCRV")));
}
} // namespace

double Bds5Motion::rate(const Bds5VariableStore& vars, const char* name) const {
    return std::max(basic(vars, name), 1.0) / kBasicPerCountPerSecond2;
}

int Bds5Motion::checkCanMove(const Bds5VariableStore& vars, bool enabled) const {
    if (!enabled) return 50;                   // DRIVE INHIBITED
    if (basic(vars, "MOTION") == 0) return 19; // MOTION (HDWR LINE)
    if (m_cam.on()) return 57;                 // profiles are not allowed while camming (L9470; number chosen)
    return 0;
}

// MRD, MA, JT, JF, MCA and NORM are refused with the gearbox on (ERR 56, L7303, L3023, L2483).
int Bds5Motion::checkNoGear(const Bds5VariableStore& vars) const {
    return basic(vars, "GEAR") != 0 ? 56 : 0;
}

int Bds5Motion::jog(const Bds5VariableStore& vars, bool enabled, std::int64_t velocity) {
    if (const int e = checkCanMove(vars, enabled)) return e;
    if (std::llabs(velocity) > std::int64_t(basic(vars, "VMAX"))) return 33; // J: within ±VMAX (L7254)
    const double target = double(velocity) / kBasicPerCountPerSecond;
    const double acc = rate(vars, "ACC");
    const double dec = rate(vars, "DEC");
    if (std::abs(target - m_profile.velocity()) / std::min(acc, dec) > kMaxRampSeconds) return 32;
    if (velocity == 0 && !m_profile.moving()) return 0;
    m_profile.jog({motion::MoveKind::Jog, 0, target, acc, dec, shape(vars)});
    return 0;
}

int Bds5Motion::move(const Bds5VariableStore& vars, bool enabled, std::int64_t target,
                     std::optional<std::int64_t> velocity, bool incremental) {
    if (const int e = checkCanMove(vars, enabled)) return e;
    if (!incremental)
        if (const int e = checkNoGear(vars)) return e;
    // Rotary mode: absolute targets must lie in 0..PROTARY (ERR 60, L7314).
    if (!incremental && basic(vars, "ROTARY") != 0 && (target < 0 || double(target) > basic(vars, "PROTARY")))
        return 60;
    const std::int64_t v = velocity.value_or(std::int64_t(basic(vars, "VDEFAULT")));
    if (v <= 0 || v > std::int64_t(basic(vars, "VMAX"))) return 33; // other moves: 0..+VMAX (L7254)
    const double acc = rate(vars, "ACC");
    const double dec = rate(vars, "DEC");
    const double cps = double(v) / kBasicPerCountPerSecond;
    if (cps / acc > kMaxRampSeconds || cps / dec > kMaxRampSeconds) return 32; // checked before motion
    if (m_profile.jogging()) return 58;                                        // NOT w/JOGGING (L7307)
    if (m_profile.full()) return 30;
    const double end = incremental ? std::round(m_profile.finalPosition()) + double(target) : toProfile(double(target));
    return m_profile.push({motion::MoveKind::Position, end, cps, acc, dec, shape(vars)}) ? 0 : 30;
}

int Bds5Motion::jogTo(const Bds5VariableStore& vars, bool enabled, std::int64_t position, std::int64_t velocity,
                      bool to) {
    if (const int e = checkCanMove(vars, enabled)) return e;
    if (const int e = checkNoGear(vars)) return e;
    if (std::llabs(velocity) > std::int64_t(basic(vars, "VMAX"))) return 33;
    const double v0 = m_profile.velocity();
    if (v0 == 0) return 41; // MOVE NEEDS MOTION
    const double direction = v0 < 0 ? -1.0 : 1.0;
    const double v1 = double(velocity) / kBasicPerCountPerSecond;
    if (v1 * direction < 0) return 40; // CHANGED DIRECTION
    const double rate = std::abs(v1) > std::abs(v0) ? this->rate(vars, "ACC") : this->rate(vars, "DEC");
    const double rampTime = std::abs(v1 - v0) / rate;
    const double rampDistance = (v0 + v1) / 2 * rampTime;
    const double ahead = toProfile(double(position)) - m_profile.position();
    const double hold = to ? ahead - rampDistance : ahead; // JT: the ramp ends there; JF: it begins there
    if (hold * direction < 0) return 42;                   // MOVE w/o TIME: already passed
    if (rampTime > kMaxRampSeconds) return 32;
    std::vector<motion::Segment> segments{{hold / v0, 0, 1}, {rampTime, v1 > v0 ? rate : -rate, 2, shape(vars)}};
    if (v1 != 0) segments.push_back({std::numeric_limits<double>::infinity(), 0, 3});
    // JT to rest lands exactly on its count (not on position + hold + ramp, which rounding leaves a hair off).
    const double stopAt = to ? toProfile(double(position)) : toProfile(double(position)) + rampDistance;
    const std::optional<double> end = v1 == 0 ? std::optional<double>(stopAt) : std::nullopt;
    m_profile.start(std::move(segments), end);
    return 0;
}

int Bds5Motion::moveRd(const Bds5VariableStore& vars, bool enabled, std::int64_t rdPosition, std::int64_t velocity,
                       int direction) {
    if (const int e = checkCanMove(vars, enabled)) return e;
    if (const int e = checkNoGear(vars)) return e;
    if (m_profile.moving()) return 31; // TOO MANY MRD MOVES: needs an empty buffer
    if (velocity <= 0 || velocity > std::int64_t(basic(vars, "VMAX"))) return 33;
    const std::int64_t perRev = 4096; // the reference 12-bit R/D
    if (rdPosition < 0 || rdPosition >= perRev) return 83;
    const std::int64_t prd = ((std::llround(commandPosition_counts()) % perRev) + perRev) % perRev;
    std::int64_t d = rdPosition - prd;
    if (direction > 0 && d < 0)
        d += perRev;
    else if (direction < 0 && d > 0)
        d -= perRev;
    else if (direction == 0 && d > perRev / 2)
        d -= perRev;
    else if (direction == 0 && d <= -perRev / 2)
        d += perRev;
    const double cps = double(velocity) / kBasicPerCountPerSecond;
    m_profile.push({motion::MoveKind::Position, m_profile.position() + double(d), cps, rate(vars, "ACC"),
                    rate(vars, "DEC"), shape(vars)});
    return 0;
}

int Bds5Motion::keepMoving(bool enabled) {
    if (!enabled) return 50;
    m_profile.start({{std::numeric_limits<double>::infinity(), 0, 1}}, std::nullopt);
    return 0;
}

int Bds5Motion::macroSection(const Bds5VariableStore& vars, std::int64_t positionOrDistance, bool absolute,
                             std::optional<std::int64_t> first, std::optional<std::int64_t> second) {
    if (m_macroId && m_profile.activeId() == m_macroId) return 48; // MCA/MCI RUNNING
    if (absolute)
        if (const int e = checkNoGear(vars)) return e;
    if (!m_macro.open() || m_macro.segments().empty()) {
        m_macro.reset();
        m_macroStart = m_profile.finalPosition();
    }
    const auto speed = [](std::optional<std::int64_t> v) {
        return v ? std::optional<double>(double(*v) / kBasicPerCountPerSecond) : std::nullopt;
    };
    if ((first && *first < 0) || (second && *second < 0)) return 83; // velocities are always positive
    const double distance = absolute
                                ? toProfile(double(positionOrDistance)) - (m_macroStart + m_macro.definedDistance())
                                : double(positionOrDistance);
    return m_macro.addSection(distance, speed(first), speed(second), rate(vars, "ACC"), rate(vars, "DEC"), shape(vars));
}

int Bds5Motion::macroDwell(std::int64_t ms) {
    if (m_macroId && m_profile.activeId() == m_macroId) return 48;
    if (ms < 0) return 83;
    if (!m_macro.open() || m_macro.segments().empty()) {
        m_macro.reset();
        m_macroStart = m_profile.finalPosition();
    }
    return m_macro.addDwell(double(ms) / 1000);
}

int Bds5Motion::macroGo(const Bds5VariableStore& vars, bool enabled) {
    if (const int e = checkCanMove(vars, enabled)) return e;
    if (m_macro.open())
        if (const int e = m_macro.close()) return e;
    if (m_profile.jogging()) return 58;
    if (m_profile.full()) return 30;
    const auto id = m_profile.push(m_macro.segments(), m_macro.definedDistance());
    if (!id) return 30;
    m_macroId = *id;
    return 0;
}

void Bds5Motion::stop(const Bds5VariableStore& vars) {
    m_profile.stop(rate(vars, "AMAX"));
}

void Bds5Motion::halt() {
    m_profile.stop(1e18);
}

int Bds5Motion::normalize(std::int64_t position) {
    if (m_profile.moving()) return 57;
    m_cam.stop();
    m_profile.setPosition(toProfile(double(position)));
    return 0;
}

int Bds5Motion::normalizeCam(const Bds5VariableStore& vars, bool enabled, std::int64_t master_counts) {
    if (!enabled) return 50;
    if (const int e = checkNoGear(vars)) return e;
    if (basic(vars, "ROTARY") != 0) return 59;
    if (m_profile.moving()) return 57;
    m_cam.start(master_counts, commandPosition_counts(), vars);
    return 0;
}

void Bds5Motion::clampStop() {
    if (m_profile.moving()) m_profile.start({}, m_profile.position());
}

SERVODESK_NO_COVERAGE int Bds5Motion::step(Microseconds dt, Bds5VariableStore& vars) {
    // GATEMODE (L5949-5971): commanded motion waits for the GATE input to go high, then GATEMODE turns off.
    // Turning GATEMODE off first makes the drive forget the motion.
    const StepRefs& r = stepRefs();
    const bool gate = vars.read(r.gate) != 0;
    const bool rising = gate && !m_gateLast;
    m_gateLast = gate;
    if (vars.read(r.gatemode) != 0) {
        m_profile.setHeld(true);
        if (m_profile.moving() && rising) {
            m_profile.setHeld(false);
            vars.set(r.gatemode, 0);
        }
    } else if (m_profile.held()) {
        m_profile.setHeld(false);
        if (m_profile.moving() && m_profile.velocity() == 0) m_profile.stop(1);
    }
    const Bds5Regulation::Tick regulated = m_regulation.step(vars, double(dt.count()) / 1e3);
    if (regulated.error) {
        stop(vars);
        writeVariables(vars);
        return regulated.error;
    }
    m_profileRate = regulated.profileFraction;
    m_profile.step(double(dt.count()) / 1e6 * regulated.profileFraction);
    if (const int e = m_gearbox.step(vars)) {
        stop(vars);
        writeVariables(vars);
        return e;
    }
    const double p = commandPosition_counts();
    if (p > double(INT32_MAX) || p < double(INT32_MIN)) { // PFB ROLLOVER (L7234): beyond ±2,147,483,647
        halt();
        m_profile.setPosition(toProfile(std::clamp(p, double(INT32_MIN), double(INT32_MAX))));
        writeVariables(vars);
        return 26;
    }
    m_cam.step(commandPosition_counts(), vars, double(dt.count()) / 1e6);
    writeVariables(vars);
    if (m_cam.on()) vars.set(r.pcam, std::int32_t(std::llround(m_cam.pcam_counts())));
    // Software limits (L2237-2259): with PFB beyond PMAX no positive motion, below PMIN no negative motion.
    // One overtravel is one ERR 23: the stop it starts keeps the motion's id while it decelerates outward,
    // so it is not raised (nor the stop restarted) again until a new command moves outward.
    if (vars.read(r.plim) != 0 && m_profile.moving() && m_profile.activeId() != m_overtravelId) {
        const double v = m_profile.velocity();
        const double pfb = vars.read(r.pfb);
        if ((v > 0 && pfb > vars.read(r.pmax)) || (v < 0 && pfb < vars.read(r.pmin))) {
            stop(vars);
            m_overtravelId = m_profile.activeId();
            return 23;
        }
    }
    return 0;
}

SERVODESK_NO_COVERAGE void Bds5Motion::writeVariables(Bds5VariableStore& vars) const {
    const auto position = std::int32_t(std::llround(commandPosition_counts()));
    const auto velocity = std::int32_t(std::llround(commandVelocity_cps() * kBasicPerCountPerSecond));
    const StepRefs& r = stepRefs();
    vars.set(r.cam, m_cam.on() ? 1 : 0);
    vars.set(r.pcmd, m_cam.on() ? std::int32_t(m_cam.pcmd_counts()) : position);
    vars.set(r.vcmd, velocity);
    vars.set(r.seg, m_profile.segment());
    vars.set(r.pfnl, std::int32_t(std::llround(m_profile.finalPosition() + double(m_gearbox.offset_counts()))));
}

SERVODESK_NO_COVERAGE void Bds5Motion::followFeedback(double pfb_counts) { // every period while inactive
    m_gearbox.stopRamp(); // inactive: RAMP's velocity command starts from rest when the drive is enabled
    if (!m_profile.moving()) m_profile.setPosition(toProfile(pfb_counts));
}

void Bds5Motion::shiftFrame(std::int64_t counts, Bds5VariableStore& vars) {
    m_gearbox.shiftFrame(counts);
    writeVariables(vars);
}

int Bds5Motion::zeroPositionError(double pfb_counts) {
    if (m_profile.moving()) return 57;
    m_profile.setPosition(toProfile(pfb_counts));
    return 0;
}

} // namespace drive_core::bds5
