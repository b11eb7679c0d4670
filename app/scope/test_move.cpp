// TestMove: presets -> RECORD plans.
#include "test_move.h"

#include "scope_catalog.h"

#include <QObject>

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
    case Kind::PositionStep:
        p.commands = {{0, QStringLiteral("MI %1").arg(amplitude)},
                      {durationMs, QStringLiteral("MI %1").arg(-amplitude)}};
        break;
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
    case Kind::PositionStep: return QObject::tr("MI %1, back after %2 ms").arg(amplitude).arg(durationMs);
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

} // namespace app
