// The master input's pulse train, steady frequency plus wave.
#include "master_signal.h"

#include <cmath>
#include <numbers>

namespace drive_core {

void MasterSignal::setWave(const MasterWave& wave) {
    m_wave = wave;
    if (!(m_wave.frequency_Hz > 0)) m_wave.shape = MasterWaveShape::None;
    m_time_us = 0;
}

double MasterSignal::advance(double dt_s) {
    const double t0 = double(m_time_us) * 1e-6;
    m_time_us += std::llround(dt_s * 1e6);
    return m_steady_Hz * dt_s + waveCounts(double(m_time_us) * 1e-6) - waveCounts(t0);
}

// Over one period u = 0..1 of a unit wave, its integral in periods: each is 0 at u = 0 and u = 1, so the
// wave itself adds no counts over whole periods (the master swings about its steady frequency).
double MasterSignal::waveCounts(double t_s) const {
    const double f = m_wave.frequency_Hz;
    const double cycles = t_s * f;
    const double u = cycles - std::floor(cycles);
    double integral = 0;
    switch (m_wave.shape) {
    case MasterWaveShape::None: return 0;
    case MasterWaveShape::Sine: // sin(2 pi u)
        integral = (1 - std::cos(2 * std::numbers::pi * u)) / (2 * std::numbers::pi);
        break;
    case MasterWaveShape::Square: // +1 for the first half period, -1 for the second
        integral = u < 0.5 ? u : 1 - u;
        break;
    case MasterWaveShape::Triangle: // 0 up to +1 at a quarter, down to -1 at three quarters, back to 0
        if (u < 0.25)
            integral = 2 * u * u;
        else if (u < 0.75)
            integral = 2 * u - 2 * u * u - 0.25;
        else
            integral = 2 * (1 - u) * (1 - u);
        break;
    }
    return m_wave.amplitude_Hz / f * integral;
}

} // namespace drive_core
