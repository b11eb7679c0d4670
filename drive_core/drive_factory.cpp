// Drive families by name.
#include "drive_factory.h"

#include "bds5/bds5_drive.h"
#include "pmc960/pmc960_drive.h"
#include "sc750/sc750_drive.h"

#include <algorithm>
#include <cctype>
#include <string>

namespace drive_core {

std::optional<DriveFamily> familyFromName(std::string_view name) {
    std::string lower(name);
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (lower == "bds5") return DriveFamily::Bds5;
    if (lower == "sc750") return DriveFamily::Sc750;
    if (lower == "pmc960") return DriveFamily::Pmc960;
    return std::nullopt;
}

std::string_view familyName(DriveFamily family) {
    switch (family) {
    case DriveFamily::Bds5: return "bds5";
    case DriveFamily::Sc750: return "sc750";
    case DriveFamily::Pmc960: return "pmc960";
    }
    return "bds5";
}

std::string_view familyTitle(DriveFamily family) {
    switch (family) {
    case DriveFamily::Bds5: return "BDS5";
    case DriveFamily::Sc750: return "SC750";
    case DriveFamily::Pmc960: return "PMC-960";
    }
    return "BDS5";
}

std::unique_ptr<Drive> makeDrive(DriveFamily family) {
    switch (family) {
    case DriveFamily::Bds5: return std::make_unique<bds5::Bds5Drive>();
    case DriveFamily::Sc750: return std::make_unique<sc750::Sc750Drive>();
    case DriveFamily::Pmc960: return std::make_unique<pmc960::Pmc960Drive>();
    }
    return nullptr;
}

} // namespace drive_core
