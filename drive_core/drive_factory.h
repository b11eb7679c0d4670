// Creates a simulated drive of a family by name, for the executables and sessions that pick one at run time.
#pragma once

#include "drive.h"

#include <memory>
#include <optional>
#include <string_view>

namespace drive_core {

// "bds5", "sc750", "pmc960" (case-insensitive). Unknown or not yet simulated families give nullopt.
std::optional<DriveFamily> familyFromName(std::string_view name);
std::string_view familyName(DriveFamily family);
// The name on the drive's nameplate and in the manuals: "BDS5", "SC750", "PMC-960".
std::string_view familyTitle(DriveFamily family);
std::unique_ptr<Drive> makeDrive(DriveFamily family);

} // namespace drive_core
