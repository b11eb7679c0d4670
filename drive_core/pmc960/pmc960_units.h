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
    // #98 (L2324): in engineering units, a speed > 0 that converts below the range's least internal speed
    // (5.7: 2 x 10 Hz at 48 kHz, 1 x 100 Hz above; chosen) would not move.
    bool velocityTooSmall(double user) const { return m_engineering && user > 0 && velocity_cps(user) < m_min_cps; }
    // #99 (L2325): in engineering units, a position or distance that converts past limit_counts (5.7: index
    // 2^31 - 1, go and normalize 2^30 counts). Without them the raw ranges (#91, #93) already hold.
    bool positionOverflows(double user, double limit_counts) const;

private:
    double m_top_cps = 192000;
    double m_velocity = 100;
    double m_accel = 1000;
    double m_position = 1;
    double m_maxAccel_cps2 = 1e7;
    double m_min_cps = 100;
    bool m_engineering = false;
};

} // namespace drive_core::pmc960
