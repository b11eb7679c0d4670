// BDS5 RECORD/PLAY buffer.
#include "bds5_recorder.h"

#include "bds5_printer.h"

#include "drive_core/catalog/bds5_catalog.h"

namespace drive_core::bds5 {

namespace cat = catalog::bds5;

int Bds5Recorder::start(int intervals, int periodMs, const std::vector<std::string>& names,
                        const Bds5VariableStore& vars, std::string& badEntry) {
    if (names.empty() || names.size() > 4) return 82;
    if (periodMs < 1 || periodMs > 60'000) { // 1 ms .. 1 minute
        badEntry = std::to_string(periodMs);
        return 83;
    }
    if (intervals < 1) {
        badEntry = std::to_string(intervals);
        return 83;
    }
    for (const std::string& name : names) {
        const auto ref = cat::findVariable(name);
        if (!ref || !vars.exists(*ref)) {
            badEntry = name;
            return 80;
        }
        // Not recordable: PE, REMOTE, TMR1-4, VAVG, VXAVG, user switches (L6372, L7013).
        if (!ref->info->recordable) {
            badEntry = name;
            return 89;
        }
    }
    if (std::int64_t(intervals) * std::int64_t(names.size()) > kRecordPoints) {
        badEntry = std::to_string(intervals);
        return 90;
    }
    m_started = true;
    m_intervals = intervals;
    m_periodMs = periodMs;
    m_names = names;
    m_samples.clear();
    // The first sample is taken at once, as RECORD runs: a command typed right after it (the trigger) can
    // never reach the first sample, however soon it arrives (issue 23: with an unpaced wire a J 1000 that
    // came within the same servo period showed in sample 0).
    takeSample(vars);
    m_sinceSample = Microseconds{0};
    return 0;
}

void Bds5Recorder::takeSample(const Bds5VariableStore& vars) {
    std::vector<std::int32_t> sample;
    for (const std::string& name : m_names) sample.push_back(vars.read(name).value_or(0));
    m_samples.push_back(std::move(sample));
}

// Every servo period: no fuzzing coverage, like the rest of the tick (tests/fuzz).
SERVODESK_NO_COVERAGE void Bds5Recorder::step(Microseconds dt, const Bds5VariableStore& vars) {
    if (!recording()) return;
    m_sinceSample += dt;
    if (m_sinceSample < std::chrono::milliseconds(m_periodMs)) return;
    m_sinceSample -= std::chrono::milliseconds(m_periodMs);
    takeSample(vars);
}

std::optional<std::string> Bds5Recorder::play() const {
    if (!m_started) return std::nullopt;
    std::string out = "RECORD " + std::to_string(m_intervals) + " " + std::to_string(m_periodMs);
    for (const std::string& name : m_names) out += " " + name;
    out += "\r\n";
    for (const auto& sample : m_samples) {
        for (const std::int32_t v : sample) out += *formatValue(v, "");
        out += "\r\n";
    }
    return out;
}

} // namespace drive_core::bds5
