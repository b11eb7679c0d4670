// TestMove: presets -> RECORD plans.
#include "test_move.h"

#include "families/bds5/record/scope_catalog.h"

#include "drive_core/bds5/bds5_loop_scaling.h"
#include "drive_core/bds5/bds5_servo.h"

#include <QObject>

#include <cmath>
#include <numbers>

namespace app {

namespace {
// Recorded past the end of the move, to see it settle back.
int recordSpanMs(const TestMove& m) {
    if (m.kind == TestMove::Kind::FrequencyStep) return m.durationMs;
    return m.kind == TestMove::Kind::BackAndForth ? 3 * m.durationMs : 2 * m.durationMs;
}
} // namespace

serialport::Bds5RecordPlan TestMove::plan() const {
    serialport::Bds5RecordPlan p;
    const bool position = kind == Kind::PositionStep;
    p.variables = {position ? QStringLiteral("PCMD") : QStringLiteral("VCMD"),
                   position ? QStringLiteral("PFB") : QStringLiteral("VFB"), QStringLiteral("ICMD")};
    if (kind == Kind::FrequencyStep) p.variables.removeLast(); // two channels: 500 points, 1 ms for 0.5 s
    const int limit = recordSampleLimit(int(p.variables.size()));
    const int span = std::max(1, recordSpanMs(*this));
    p.intervalMs = std::max(1, (span + limit - 1) / limit);
    p.samples = std::min(limit, std::max(1, span / p.intervalMs));
    switch (kind) {
    case Kind::VelocityStep:
        p.commands = {{0, QStringLiteral("J %1").arg(amplitude)}, {durationMs, QStringLiteral("J 0")}};
        p.onCancel = QStringLiteral("J 0");
        break;
    case Kind::PositionStep: {
        const QString speed = moveVelocity > 0 ? QStringLiteral(" %1").arg(moveVelocity) : QString();
        p.commands = {{0, QStringLiteral("MI %1").arg(amplitude) + speed},
                      {durationMs, QStringLiteral("MI %1").arg(-amplitude) + speed}};
        break;
    }
    case Kind::BackAndForth:
        p.commands = {{0, QStringLiteral("J %1").arg(amplitude)},
                      {durationMs, QStringLiteral("J %1").arg(-amplitude)},
                      {2 * durationMs, QStringLiteral("J 0")}};
        p.onCancel = QStringLiteral("J 0");
        break;
    case Kind::FrequencyStep:
        // The Bode view's excitation. A chirp of J commands cannot be sent: at 9600 baud each "J v" with its
        // echo and prompt takes about 10 ms, so the command could not change faster than ~50 Hz. A velocity
        // step is broadband instead (its difference is an impulse, see scope/frequency_response.h); it is
        // held to the end of the record so the spectrum has no zeros, and J 0 goes out once it is over.
        p.commands = {{0, QStringLiteral("J %1").arg(amplitude)}, {durationMs, QStringLiteral("J 0")}};
        p.onCancel = QStringLiteral("J 0");
        break;
    }
    return p;
}

QString TestMove::description() const {
    switch (kind) {
    case Kind::VelocityStep: return QObject::tr("J %1 for %2 ms, then J 0").arg(amplitude).arg(durationMs);
    case Kind::PositionStep:
        return moveVelocity > 0
                   ? QObject::tr("MI %1 at %2, back after %3 ms").arg(amplitude).arg(moveVelocity).arg(durationMs)
                   : QObject::tr("MI %1, back after %2 ms").arg(amplitude).arg(durationMs);
    case Kind::BackAndForth:
        return QObject::tr("J %1, J %2 after %3 ms, then J 0").arg(amplitude).arg(-amplitude).arg(durationMs);
    case Kind::FrequencyStep:
        return QObject::tr("J %1 held for the %2 ms record, then J 0").arg(amplitude).arg(durationMs);
    }
    return {};
}

QString TestMove::kindName(Kind kind) {
    switch (kind) {
    case Kind::VelocityStep: return QObject::tr("Velocity step");
    case Kind::PositionStep: return QObject::tr("Position step");
    case Kind::BackAndForth: return QObject::tr("Back and forth");
    case Kind::FrequencyStep: return QObject::tr("Step for frequency response");
    }
    return {};
}

QStringList TestMove::proposalInputs() {
    return {QStringLiteral("ILIM"), QStringLiteral("IMAX"), QStringLiteral("KV"),   QStringLiteral("VMAX"),
            QStringLiteral("ACC"),  QStringLiteral("VNUM"), QStringLiteral("VDEN"), QStringLiteral("ANUM"),
            QStringLiteral("ADEN"), QStringLiteral("PNUM"), QStringLiteral("PDEN")};
}

// The proposal, from the velocity loop's law (L3204-3206, drive_core/bds5/bds5_loop_scaling.h):
//   ICMD/IMAX = KV' (KVI' integral(VE) - VFB),  KV' = KV * kKvFractionPerRadPerS,
// whose closed loop is wn^2 / (s^2 + 2 zeta wn s + wn^2) with 2 zeta wn = a = Kt Ipeak KV' / J. The motor's
// acceleration is a * ICMD/IMAX / KV', so for a velocity step dv (faster than the loop, the worst case)
//   peak ICMD/IMAX = KV' * dv * p(zeta),  p = max of the normalised impulse response / (2 zeta):
// p = 1/(2e) = 0.18 at critical damping (what tuning aims at), 0.32 at zeta 0.7. The inertia cancels, so only
// the drive's values are needed. Solving for dv with ICMD at kIlimShare of ILIM and p = 0.18:
//   dv [rad/s] = kIlimShare * (ILIM / IMAX) * 2e / KV'
// which keeps ICMD below 0.9 ILIM down to zeta 0.7. ACC's ramp only lowers the peak (the formula is the
// worst case, a command faster than the loop): at the power-up ACC a 1300 RPM step ramps for 13 ms. In user units: RPM
// = VEL * (VNUM/VDEN) / 4473.9 (L1521-1560). Capped at half of VMAX. A back-and-forth reverses by 2 dv, so it gets half
// of it. A position step is MI at its own speed (VDEFAULT is 1 RPM at power-up): the speed reached accelerating at ACC
// (RPM/s = ACC * (ANUM/ADEN) / 4.474) for a quarter of the hold, at most dv, and the distance that speed covers in a
// quarter of the hold (the triangle's area), so the move is over within half of it; counts = units * PNUM/PDEN, 4096
// counts a turn. Its current is set by ACC, not by the distance: lower ACC when the warning still shows.
namespace {
double driveValue(const TestMove::DriveValues& drive, const char* name, double powerUp) {
    const double v = drive.value(QString::fromLatin1(name), powerUp);
    return v > 0 ? v : powerUp;
}

// The drive's units (L1521-1560), at their power-up values until read.
double rpmPerVelocityUnit(const TestMove::DriveValues& drive) {
    return driveValue(drive, "VNUM", 44739) / driveValue(drive, "VDEN", 10) / 4473.9;
}

double countsPerPositionUnit(const TestMove::DriveValues& drive) {
    return driveValue(drive, "PNUM", 1) / driveValue(drive, "PDEN", 1);
}

// The proposal's figures in SI units, from the drive's values (see above).
struct Proposal {
    double rpmPerVel = 1, countsPerUnit = 1;
    double step_radPerS = 0; // the velocity step
    double move_radPerS = 0; // the position step's peak speed
    double moveTurns = 0;    // and its distance
};

Proposal propose(int durationMs, const TestMove::DriveValues& drive) {
    namespace ls = drive_core::bds5::loop_scaling;
    const auto value = [&drive](const char* name, double powerUp) { return driveValue(drive, name, powerUp); };
    Proposal p;
    p.rpmPerVel = rpmPerVelocityUnit(drive);
    p.countsPerUnit = countsPerPositionUnit(drive);
    const double rpmPerSPerAcc = value("ANUM", 4474) / value("ADEN", 1000) / 4.474;
    const double radPerSPerRpm = 2 * std::numbers::pi / 60;
    const double kvPrime = value("KV", 2000) * ls::kKvFractionPerRadPerS;
    const double share = TestMove::kIlimShare * std::min(1.0, value("ILIM", 100) / value("IMAX", 100));
    p.step_radPerS = std::min(share * 2 * std::numbers::e / kvPrime,
                              0.5 * value("VMAX", 7500 / p.rpmPerVel) * p.rpmPerVel * radPerSPerRpm);
    const double acc_radPerS2 = value("ACC", 100000 / rpmPerSPerAcc) * rpmPerSPerAcc * radPerSPerRpm;
    const double quarter_s = durationMs / 4000.0;
    p.move_radPerS = std::min(acc_radPerS2 * quarter_s, p.step_radPerS);
    p.moveTurns = p.move_radPerS * quarter_s / (2 * std::numbers::pi);
    return p;
}

int atLeastOne(double v) {
    return std::max(1, int(std::lround(v)));
}
} // namespace

int TestMove::proposedAmplitude(Kind kind, int durationMs, const DriveValues& drive) {
    const Proposal p = propose(durationMs, drive);
    const double stepVel = p.step_radPerS * 60 / (2 * std::numbers::pi) / p.rpmPerVel;
    switch (kind) {
    case Kind::VelocityStep:
    case Kind::FrequencyStep: return atLeastOne(stepVel);
    case Kind::BackAndForth: return atLeastOne(stepVel / 2);
    case Kind::PositionStep: return atLeastOne(p.moveTurns * drive_core::bds5::kCountsPerRev / p.countsPerUnit);
    }
    return 1;
}

int TestMove::proposedMoveVelocity(int durationMs, const DriveValues& drive) {
    const Proposal p = propose(durationMs, drive);
    return atLeastOne(p.move_radPerS * 60 / (2 * std::numbers::pi) / p.rpmPerVel);
}

TestMove::Travel TestMove::travel(const DriveValues& drive) const {
    const double jog_rps = amplitude * rpmPerVelocityUnit(drive) / 60;
    const double jog_counts = jog_rps * drive_core::bds5::kCountsPerRev * (durationMs / 1000.0);
    const double jog_units = jog_counts / countsPerPositionUnit(drive);
    // A back-and-forth comes back as far as it went; the frequency step's J is held for its whole duration.
    const double reach_units = kind == Kind::PositionStep ? double(amplitude) : jog_units;
    return {std::min(0.0, reach_units), std::max(0.0, reach_units)};
}

} // namespace app
