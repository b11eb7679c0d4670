// PMC-960 units: user values to counts, counts/s and counts/s², by velocity range or engineering units
// (5.7 L881-909, TUA/TUP/TUS L2050-2115). chosen (digest §5.2 inferred): the range is the smallest of 48, 192
// and 384 kHz holding TUS x TUV Hz; without engineering units values are in the range's internal units.
#pragma once

#include "pmc960_table.h"

namespace drive_core::pmc960 {

class Pmc960Units {
public:
    Pmc960Units(const Pmc960Table& table, bool engineering);

    double topSpeed_cps() const { return m_top_cps; } // 48000, 192000 or 384000
    double velocity_cps(double user) const { return user * m_velocity; }
    double accel_cps2(double user) const { return user * m_accel; }
    double position_counts(double user) const { return user * m_position; }
    double userVelocity(double cps) const { return cps / m_velocity; }
    double userAccel(double cps2) const { return cps2 / m_accel; }
    double userPosition(double counts) const { return counts / m_position; }
    // The largest user speed the range allows (V, J, H, C ranges; #94 beyond).
    double maximumUserVelocity() const { return m_top_cps / m_velocity; }
    // The emergency and limit deceleration (TUB), counts/s².
    double maximumAccel_cps2() const { return m_maxAccel_cps2; }

private:
    double m_top_cps = 192000;
    double m_velocity = 100;
    double m_accel = 1000;
    double m_position = 1;
    double m_maxAccel_cps2 = 1e7;
};

} // namespace drive_core::pmc960
