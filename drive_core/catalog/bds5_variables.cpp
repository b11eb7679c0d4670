// BDS5 variables (App. E Table E.1 L7553-7684, v3.0.0 L9299-9325, Table E.3 L7697-7721).
// STUB: being completed to all variables.
#include "bds5_catalog.h"

#include <array>

namespace drive_core::catalog::bds5 {
namespace {
constexpr std::array kVariables{
    VariableInfo{.name = "X", .firstIndex = 1, .lastIndex = 250, .description = "User variable",
                 .limits = LimitClass::Long, .group = VariableGroup::User, .manualLines = "L1572-1645"},
    VariableInfo{.name = "XS", .firstIndex = 1, .lastIndex = 50, .description = "User switch",
                 .limits = LimitClass::Switch, .group = VariableGroup::User, .isSwitch = true,
                 .recordable = false, .manualLines = "L1572-1645"},
    VariableInfo{.name = "VMAX", .description = "Maximum velocity", .units = "VEL",
                 .unitClass = UnitClass::Velocity, .limits = LimitClass::LongPositive,
                 .powerUpValue = 0, .group = VariableGroup::Limits, .manualLines = ""},
};
} // namespace

std::span<const VariableInfo> variables() { return kVariables; }

} // namespace drive_core::catalog::bds5
