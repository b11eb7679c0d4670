// PMC-960 unit conversions.
#include "pmc960_units.h"

#include <algorithm>
#include <cmath>

namespace drive_core::pmc960 {

Pmc960Units::Pmc960Units(const Pmc960Table& table, bool engineering) {
    const double tus = double(table.inUse("TUS")) / 10000.0;
    const double tua = double(table.inUse("TUA")) / 10000.0;
    const double tup = double(table.inUse("TUP")) / 10000.0;
    const double wanted = tus * double(table.inUse("TUV"));
    const bool range48 = wanted > 0 && wanted <= 48000;
    m_top_cps = range48 ? 48000 : wanted <= 192000 ? 192000 : 384000;
    m_min_cps = range48 ? 20 : 100;
    m_engineering = engineering;
    if (engineering) {
        m_velocity = std::max(tus, 1e-6);
        m_accel = std::max(tua, 1e-6);
        m_position = std::max(tup, 1e-6);
    } else { // the internal units of 5.7's table
        m_velocity = range48 ? 10 : 100;
        m_accel = range48 ? 100 : 1000;
        m_position = 1;
    }
    m_maxAccel_cps2 = std::max(1.0, double(table.inUse("TUB")) * m_accel);
}

bool Pmc960Units::positionOverflows(double user, double limit_counts) const {
    return m_engineering && std::abs(position_counts(user)) > limit_counts;
}

} // namespace drive_core::pmc960
