// MonitorRecorder: the bench's oscilloscope on a simulated drive's analog monitor output (issue 18) — the
// test point a technician probes while tuning: the SC750's DACMON (the signal DACMAP selects) and the
// PMC-960's tachometer signal (§4.8). The drive pushes one sample a servo period; the bench hands out the
// newest kCapacity of them (SimulatorControls::analogMonitor). A second probe may record the velocity loop's
// command beside it, the same period. A fixed ring, no allocation per sample.
#pragma once

#include "simulator_controls.h"

#include <array>
#include <cstddef>

namespace drive_core {

class MonitorRecorder {
public:
    static constexpr std::size_t kCapacity = 8192; // SC750: 3.5 s at 0.427 ms; PMC-960: 4.1 s at 0.5 ms

    explicit MonitorRecorder(double interval_s) : m_interval_s(interval_s) {}

    void push(double volts, double driveTime_s) { push(volts, 0.0, driveTime_s, false); }
    // The output and, on the second probe, the velocity loop's command in the same period.
    void push(double volts, double command, double driveTime_s, bool hasCommand = true) {
        m_hasCommand = hasCommand;
        m_command[m_next] = float(command);
        m_samples[m_next] = float(volts);
        m_next = (m_next + 1) % kCapacity;
        if (m_count < kCapacity) ++m_count;
        m_lastTime_s = driveTime_s;
    }
    void clear() { m_count = m_next = 0; }

    // The samples held, oldest first, named `signal` (and the command's `commandSignal`).
    MonitorTrace trace(std::string signal, std::string commandSignal = {}) const {
        MonitorTrace t;
        t.signal = std::move(signal);
        t.interval_s = m_interval_s;
        t.lastSample_s = m_lastTime_s;
        t.volts.reserve(m_count);
        for (std::size_t i = 0; i < m_count; ++i) t.volts.push_back(m_samples[index(i)]);
        if (!m_hasCommand) return t;
        t.commandSignal = std::move(commandSignal);
        t.command.reserve(m_count);
        for (std::size_t i = 0; i < m_count; ++i) t.command.push_back(m_command[index(i)]);
        return t;
    }

private:
    std::size_t index(std::size_t i) const { return (m_next + kCapacity - m_count + i) % kCapacity; }

    double m_interval_s;
    std::array<float, kCapacity> m_samples{};
    std::array<float, kCapacity> m_command{};
    bool m_hasCommand = false;
    std::size_t m_next = 0;
    std::size_t m_count = 0;
    double m_lastTime_s = 0;
};

} // namespace drive_core
