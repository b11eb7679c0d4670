// BDS5 electronic camming (v3.0, L9358-9569): the gearbox output PCMD, taken modulo 32768 counts, indexes
// the 128-point table X100-X227 with 256 linearly interpolated steps between points; the result is PCAM,
// the command the position loop follows (PE = PCAM - PFB).
#pragma once

#include "bds5_variable_store.h"

#include <cstdint>

namespace drive_core::bds5 {

constexpr std::int64_t kCamCycle_counts = 32768; // one master cycle of PCMD (128 points x 256)
constexpr int kCamFirstRegister = 100;           // X100 = master 0 degrees
constexpr int kCamPoints = 128;

class Bds5Cam {
public:
    // NORM <master> CAM: PCMD reads `master_counts` (mod 32768) while the command is at command_counts.
    void start(std::int64_t master_counts, double command_counts, const Bds5VariableStore& vars);
    void stop() { m_on = false; }
    bool on() const { return m_on; }

    // One servo period: PCMD from the gearbox command, PCAM from the table. Velocity of PCAM in counts/s.
    void step(double command_counts, const Bds5VariableStore& vars, double period_s);
    std::int64_t pcmd_counts() const { return m_pcmd; }
    double pcam_counts() const { return m_pcam; }
    double pcamVelocity_cps() const { return m_pcamVelocity_cps; }

    // The table's value at PCMD (0..32767), linearly interpolated (the cycle wraps X227 -> X100).
    static double lookup(std::int64_t pcmd_counts, const Bds5VariableStore& vars);

private:
    bool m_on = false;
    double m_origin_counts = 0; // PCMD - the gearbox command at NORM
    std::int64_t m_pcmd = 0;
    double m_pcam = 0;
    double m_pcamVelocity_cps = 0;
};

} // namespace drive_core::bds5
