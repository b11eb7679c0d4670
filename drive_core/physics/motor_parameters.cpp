// The reference motor/drive combinations.
#include "motor_parameters.h"

#include <algorithm>
#include <array>

namespace drive_core::physics {

namespace {
// chosen: three sizes covering the BDS5's range (a few hundred W to a few kW), round numbers.
const std::array kMotors{
    ReferenceMotor{"REF-SMALL", "0.4 kW, 0.75 Nm continuous, 7500 RPM, low inertia",
                   MotorParameters{0.25, 2.5e-5, 5e-6, 0.01, 3, 9, 7500, 1200}},
    ReferenceMotor{"REF-MEDIUM", "1.2 kW, 3 Nm continuous, 6000 RPM (the default)",
                   MotorParameters{0.5, 1.5e-4, 2e-5, 0.02, 6, 18, 6000, 1000}},
    ReferenceMotor{"REF-LARGE", "3.5 kW, 14 Nm continuous, 3000 RPM, high inertia",
                   MotorParameters{1.2, 1.2e-3, 1e-4, 0.08, 12, 36, 3000, 800}},
};
} // namespace

std::span<const ReferenceMotor> referenceMotors() {
    return kMotors;
}

const ReferenceMotor* findReferenceMotor(std::string_view name) {
    const auto it =
        std::find_if(kMotors.begin(), kMotors.end(), [name](const ReferenceMotor& m) { return m.name == name; });
    return it == kMotors.end() ? nullptr : &*it;
}

} // namespace drive_core::physics
