// The simulated master (external encoder / analog) input's pulse train: a steady frequency plus a
// MasterWave, integrated exactly so that no count is gained or lost however the periods fall.
#pragma once

#include "simulator_controls.h"

#include <cstdint>

namespace drive_core {

class MasterSignal {
public:
    void setFrequency_Hz(double countsPerSecond) { m_steady_Hz = countsPerSecond; }
    // The wave starts now, at its zero crossing (rising for the sine and triangle, high for the square).
    void setWave(const MasterWave& wave);
    double frequency_Hz() const { return m_steady_Hz; }
    const MasterWave& wave() const { return m_wave; }
    bool idle() const { return m_steady_Hz == 0 && m_wave.shape == MasterWaveShape::None; }

    // Lets dt_s pass and returns the counts the master sent meanwhile (fractional: the caller carries the
    // fraction to the next period).
    double advance(double dt_s);

private:
    // The wave's counts from its start to t_s (its integral; zero at every whole period).
    double waveCounts(double t_s) const;

    double m_steady_Hz = 0;
    MasterWave m_wave;
    std::int64_t m_time_us = 0; // since the wave started (whole microseconds: no drift over hours)
};

} // namespace drive_core
