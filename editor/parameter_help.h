// Help pages for a drive parameter and an error, the same for every family: rendered from the common catalog
// schema (drive_core/catalog/drive_catalog.h), so the BDS5's VMAX, the SC750's KVP and the PMC-960's TGP
// read alike: kind, units, range, when writable, power-up value, the manual's words and where it says so.
#pragma once

#include "drive_core/catalog/drive_catalog.h"

#include <QString>

namespace editor {

QString parameterHelpHtml(const drive_core::catalog::Parameter& parameter);
// codePrefix goes before the code as the drive prints it: "ERR " for the BDS5 ("ERR 25"), "" elsewhere.
QString errorHelpHtml(const drive_core::catalog::ErrorEntry& error, const QString& codePrefix = {});
// The family's parameter whose name (an indexed family's stem) is `name`; nullptr when none.
const drive_core::catalog::Parameter* parameterNamed(drive_core::DriveFamily family, std::string_view name);

} // namespace editor
