// The electronic gearbox (L2923-3042, digest §7.11, §7.20): with GEAR on, every external (master) count
// moves the command by GEARI/GEARO counts, the fraction carried so no pulse is lost, plus the velocity
// offset VOFF. Its output is an offset summed onto the profile (so MI and J add to the gearbox). Run as a
// velocity loop (PL off) with RAMP on, its velocity command slews at ACC and DEC (L3033-3042).
#pragma once

#include "bds5_variable_store.h"

#include <array>
#include <cstdint>
#include <optional>

namespace drive_core::bds5 {

class Bds5Gearbox {
public:
    // One 1 ms servo period: reads GEAR, GEARI, GEARO, VOFF and PEXT (the master counts). Returns 97 GEAR
    // OVERFLOW when the geared rate passes 2 MHz, else 0.
    int step(const Bds5VariableStore& vars);

    // The counts the gearbox has added to the command since power-up (it keeps them after GEAR OFF).
    std::int64_t offset_counts() const { return m_offset_counts; }
    // The rotary roll-over moves the frame the command is counted in (the profile's positions are
    // relative to this offset, so the roll-over is a change of this one number).
    void shiftFrame(std::int64_t counts) { m_offset_counts += counts; }
    // Its velocity command over the last period, counts/s: the geared master plus VOFF (0 with GEAR off),
    // slewed at ACC/DEC while RAMP is on with PL off.
    double velocity_cps() const { return m_velocity_cps; }
    // Not active (disabled): RAMP's slew starts again from rest.
    void stopRamp() { m_velocity_cps = 0; }

private:
    double ramp(double target_cps, const Bds5VariableStore& vars) const;

    std::int64_t m_offset_counts = 0;
    std::int64_t m_remainder = 0; // master counts x GEARI not yet a whole output count (0 <= r < GEARO)
    double m_offsetFraction = 0;  // VOFF's fraction of a count
    double m_velocity_cps = 0;
    std::optional<std::int32_t> m_masterLast;
    std::array<std::int64_t, 16> m_recent{}; // master counts of the last 16 ms, for the 2 MHz check
    std::size_t m_recentAt = 0;
    std::int64_t m_recentSum = 0;
};

} // namespace drive_core::bds5
