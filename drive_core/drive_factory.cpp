// Drive families by name.
#include "drive_factory.h"

#include "bds5/bds5_drive.h"
#include "pmc960/pmc960_drive.h"
#include "sc750/sc750_drive.h"

#include <algorithm>
#include <cctype>
#include <string>

namespace drive_core {

namespace {
struct FamilyNames {
    DriveFamily family;
    std::string_view key;   // "bds5": command lines, settings, file names
    std::string_view title; // "BDS5": the nameplate
};
constexpr FamilyNames kFamilies[] = {
    {DriveFamily::Bds5, "bds5", "BDS5"},
    {DriveFamily::Sc750, "sc750", "SC750"},
    {DriveFamily::Pmc960, "pmc960", "PMC-960"},
};
const FamilyNames& names(DriveFamily family) {
    for (const FamilyNames& f : kFamilies)
        if (f.family == family) return f;
    return kFamilies[0];
}
} // namespace

std::optional<DriveFamily> familyFromName(std::string_view name) {
    std::string lower(name);
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    for (const FamilyNames& f : kFamilies)
        if (lower == f.key) return f.family;
    return std::nullopt;
}

std::string_view familyName(DriveFamily family) {
    return names(family).key;
}

std::string_view familyTitle(DriveFamily family) {
    return names(family).title;
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
