// RECORD and PLAY (L6370-6397, L6991-6993, L7011-7037): 1-4 variables sampled every t ms for n
// intervals, at most 1000 points, played back over the serial port. The PLAY layout is not in the seed;
// chosen so a host can parse it without knowing what was asked: a first line repeating the set-up,
// "RECORD <n> <t> <v1> [v2 v3 v4]", then one line per sample with each value in user units
// right-justified in 12 columns, as P prints it.
#pragma once

#include "bds5_variable_store.h"

#include "drive_core/drive.h"

#include <optional>
#include <string>
#include <vector>

namespace drive_core::bds5 {

constexpr int kRecordPoints = 1000; // total points (n x variables), ERR 90 beyond (L7425)

class Bds5Recorder {
public:
    // Checks and starts a recording; 0 or the error number (80 no such variable in vars now, 82, 83, 89 not
    // recordable, 90 too many points). On an error the variable at fault is named through badEntry.
    int start(int intervals, int periodMs, const std::vector<std::string>& names, const Bds5VariableStore& vars,
              std::string& badEntry);
    void clear() { *this = Bds5Recorder{}; }

    // Samples when a period has passed (call every simulated millisecond).
    void step(Microseconds dt, const Bds5VariableStore& vars);

    bool hasRecording() const { return m_started; }
    bool recording() const { return m_started && int(m_samples.size()) < m_intervals; }
    // The PLAY listing, CR LF terminated lines; nullopt if nothing was recorded since power-up (ERR 65).
    std::optional<std::string> play() const;

private:
    void takeSample(const Bds5VariableStore& vars);

    bool m_started = false;
    int m_intervals = 0;
    int m_periodMs = 1;
    std::vector<std::string> m_names;
    std::vector<std::vector<std::int32_t>> m_samples;
    Microseconds m_sinceSample{0};
};

} // namespace drive_core::bds5
