// BDS5 variables, part 2: the v3.0.0, text-only and internal (Table E.3) variables; variables() appends them
// to the standard table of bds5_variables.cpp.
#pragma once

#include "bds5_catalog.h"

namespace drive_core::catalog::bds5 {

std::span<const VariableInfo> moreVariables();

} // namespace drive_core::catalog::bds5
