// Bds5Drive, servo side: the 1 ms servo period (profile, loops, plant), the enable chain of §6.4 (READY,
// ACTIVE, STATUS, FAULT, OK2EN), the hardware inputs that stop motion (LIMIT, MOTION), the master input,
// position capture on HOME (CAP/CAPDIR/PCAP), the trip points (TRIP1/TRIP2), clamping (CLAMP/PECLAMP) and
// feedback loss (ERR 17).
#include "bds5_drive.h"

#include "drive_core/catalog/bds5_catalog.h"

#include <cmath>
#include <numbers>

namespace drive_core::bds5 {

namespace cat = catalog::bds5;

namespace {
constexpr Microseconds kServoPeriod{1000};
constexpr double kBasicPerCps = 65.536;

// The variables the servo period reads and writes, resolved once to their slots.
using Slot = Bds5VariableStore::Slot;
struct ChainRefs {
    Slot remote, motion, limit, ready, active, status, statmode, fault, ok2en, pcmd, vcmd, pext, vext, home;
    Slot cap, capdir, pcap, trip, trip1, trip2, ptrip1, ptrip2, pfb, clamp, peclamp, pe, extloop;
    Slot plim, pmax, pmin;
};
const ChainRefs& chainRefs() {
    static const ChainRefs r = [] {
        const auto f = [](const char* name) {
            return Bds5VariableStore::slotOf(cat::findVariable(name).value_or(cat::VariableRef{}));
        };
        return ChainRefs{f("REMOTE"),   f("MOTION"), f("LIMIT"),   f("READY"),  f("ACTIVE"), f("STATUS"),
                         f("STATMODE"), f("FAULT"),  f("OK2EN"),   f("PCMD"),   f("VCMD"),   f("PEXT"),
                         f("VEXT"),     f("HOME"),   f("CAP"),     f("CAPDIR"), f("PCAP"),   f("TRIP"),
                         f("TRIP1"),    f("TRIP2"),  f("PTRIP1"),  f("PTRIP2"), f("PFB"),    f("CLAMP"),
                         f("PECLAMP"),  f("PE"),     f("EXTLOOP"), f("PLIM"),   f("PMAX"),   f("PMIN")};
    }();
    return r;
}
bool on(const Bds5VariableStore& vars, Slot ref, bool fallback) {
    return ref.valid() ? vars.read(ref) != 0 : fallback;
}
void put(Bds5VariableStore& vars, Slot ref, std::int64_t value) {
    if (ref.valid()) vars.set(ref, std::int32_t(value));
}
} // namespace

void Bds5Drive::runServo(Microseconds dt) {
    m_servoRemainder += dt;
    while (m_servoRemainder >= kServoPeriod) {
        m_servoRemainder -= kServoPeriod;
        servoTick();
    }
}

// One servo period. ACTIVE = READY and REMOTE (Area 5): only an active drive controls the motor; otherwise
// PCMD follows PFB, VCMD and PE are 0 and the motor coasts (L2115).
void Bds5Drive::servoTick() {
    const ChainRefs& r = chainRefs();
    auto& vars = m_state.variables;
    masterInput();
    homeAndCapture();
    // Broken resolver wires (the bench): ERR 17 FEEDBACK LOSS, severity 3, while the drive is enabled.
    if (!m_bench.feedbackConnected && m_state.enabled) raiseFault(17);
    if (!m_state.enabled) m_state.motion.camOff(); // disabling ends camming (L9472)
    bool active = m_state.enabled && on(vars, r.remote, true);
    const bool extloop = on(vars, r.extloop, false);
    // Disabled, PCMD follows the feedback the loop closes on (PFB, or PEXT with EXTLOOP).
    const auto loopFeedback = [&] {
        return extloop ? std::int64_t(vars.read(r.pext)) : m_state.servo.feedback_counts();
    };
    if (!active) m_state.motion.followFeedback(double(loopFeedback()));
    // MOTION dropping during a motion command: ERR 19, stop as S (L2196-2210).
    if (m_state.motion.moving() && !on(vars, r.motion, true) && m_state.motion.commandVelocity_cps() != 0 &&
        !m_motionStopped) {
        m_motionStopped = true;
        raiseFault(19);
    } else if (!m_state.motion.moving()) {
        m_motionStopped = false;
    }
    // A gear overflow disables the drive; it is not raised again while the drive stays disabled.
    if (const int fault = m_state.motion.step(kServoPeriod, vars); fault && (fault != 97 || active)) raiseFault(fault);
    active = m_state.enabled && on(vars, r.remote, true);
    // EXTLOOP (L3115-3133): an encoder on the motor, of the resolver's resolution, feeds PEXT and the
    // position loop closes on it: PE = PCMD - PEXT (the loop sees the target shifted by PEXT - PFB).
    const std::int64_t pfbBefore = m_state.servo.feedback_counts();
    const double extShift = extloop ? double(vars.read(r.pext)) - double(vars.read(r.pfb)) : 0.0;
    const int loopFault = m_state.servo.tick(m_state.motion.servoTarget_counts() - extShift,
                                             m_state.motion.servoTargetVelocity_cps(), active, vars);
    if (extloop) {
        put(vars, r.pext, std::int64_t(vars.read(r.pext)) + (m_state.servo.feedback_counts() - pfbBefore));
        if (active) put(vars, r.pe, std::llround(m_state.motion.servoTarget_counts()) - vars.read(r.pext));
    }
    // Rotary mode (L5256): PFB outside 0..PROTARY rolls PFB, PCMD and PFNL over together, so PE, the
    // motion under way and the moves queued behind it carry on as if nothing happened. Disabled too: a
    // shaft turned by hand rolls over the same way.
    if (const std::int64_t shift = m_rotary.rollover(m_state.servo.feedback_counts(), vars)) {
        m_state.servo.shift(shift);
        m_state.motion.shiftFrame(shift, vars);
        put(vars, r.pfb, m_state.servo.feedback_counts());
    }
    // Clamping (L2659-2732): PE beyond PECLAMP while a profile runs means the part met a stop: the profile
    // stops there (SEG 0, PCMD frozen) and the loop holds against it at ILIM; PE stays near PECLAMP.
    if (active && m_state.motion.moving() && on(vars, r.clamp, false) &&
        std::abs(vars.read(r.pe)) > vars.read(r.peclamp))
        m_state.motion.clampStop();
    if (!active) {
        put(vars, r.pcmd, loopFeedback());
        put(vars, r.vcmd, 0);
    }
    if (loopFault && active) raiseFault(loopFault);
    // Camming: PFB beyond PMAX/PMIN with PLIM on is ERR 23 and, unlike without camming, disables (L9472).
    if (active && m_state.motion.camming() && on(vars, r.plim, true)) {
        const std::int32_t pfb = vars.read(r.pfb);
        if (pfb > vars.read(r.pmax) || pfb < vars.read(r.pmin)) {
            raiseFault(23);
            m_state.enabled = false;
            m_state.motion.halt();
            m_state.motion.camOff();
        }
    }
    // The hardware LIMIT input opening while enabled: ERR 24, disable, the motor coasts (L2245-2249).
    if (m_state.enabled && !on(vars, r.limit, true)) raiseFault(24);
    // The latches (Fig 3.1, L2076-2125): READY is set by EN and reset by K, DIS or a fault.
    const bool ready = m_state.enabled;
    active = ready && on(vars, r.remote, true);
    put(vars, r.ready, ready);
    put(vars, r.active, active);
    put(vars, r.status, on(vars, r.statmode, false) ? ready : active);
    put(vars, r.ok2en, on(vars, r.limit, true) ? 1 : 0);
    // Trip points (L2262-2275): TRIP1 = PFB >= PTRIP1, TRIP2 = PFB >= PTRIP2, while TRIP is on.
    if (on(vars, r.trip, true)) {
        const std::int32_t pfb = vars.read(r.pfb);
        put(vars, r.trip1, pfb >= vars.read(r.ptrip1));
        put(vars, r.trip2, pfb >= vars.read(r.ptrip2));
    }
    m_state.recorder.step(kServoPeriod, vars);
}

// The HOME input: set by the bench, or by the simulated switch that is closed while the shaft is within
// kHomeWindow_rev of its position. Capture (L2615-2657): with CAP on, the edge CAPDIR asks for (1: 0 to 1,
// 0: 1 to 0) stores PFB in PCAP and turns CAP off. The simulated switch's edge is placed exactly where the
// shaft crossed the window's border (the BDS5 captures to within 25 µs); a bench change counts at the tick.
void Bds5Drive::homeAndCapture() {
    const ChainRefs& r = chainRefs();
    auto& vars = m_state.variables;
    const double angle = m_state.servo.plant().motorAngle_rad();
    const double rev = angle / (2 * std::numbers::pi);
    std::optional<double> edge_rev;
    if (m_bench.homeAt_rev) {
        const double low = *m_bench.homeAt_rev - kHomeWindow_rev, high = *m_bench.homeAt_rev + kHomeWindow_rev;
        const bool inside = rev > low && rev < high;
        if (inside != m_homeLast) // entering: the border it came from; leaving: the border it went past
            edge_rev = inside ? (m_homeLastRev <= low ? low : high) : (rev >= high ? high : low);
        put(vars, r.home, inside);
    }
    m_homeLastRev = rev;
    const bool home = on(vars, r.home, false);
    if (home == m_homeLast) return;
    m_homeLast = home;
    if (!on(vars, r.cap, false) || home != on(vars, r.capdir, true)) return;
    const double at = edge_rev ? *edge_rev * 2 * std::numbers::pi : angle;
    put(vars, r.pcap, m_state.servo.feedbackAt(at));
    put(vars, r.cap, 0);
}

// The master (external encoder or analog) input: PEXT counts, VEXT its frequency, from the bench's steady
// frequency and wave; VEXT is the frequency over the last period (the counts it brought, per second).
void Bds5Drive::masterInput() {
    if (m_bench.master.idle()) return;
    const ChainRefs& r = chainRefs();
    const double counts = m_bench.master.advance(1e-3);
    if (on(m_state.variables, r.extloop, false)) return; // the external input carries the motor's encoder
    m_masterFraction += counts;
    // A sum within a hair of a whole count is that count (the wave's integral is exact only to rounding).
    const double whole = std::floor(m_masterFraction + 1e-9);
    m_masterFraction -= whole;
    if (r.pext.valid())
        m_state.variables.set(r.pext, std::int32_t(std::int64_t(m_state.variables.read(r.pext)) + std::int64_t(whole)));
    put(m_state.variables, r.vext, std::llround(counts * 1e3 * kBasicPerCps));
}

} // namespace drive_core::bds5
