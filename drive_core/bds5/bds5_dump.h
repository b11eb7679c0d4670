// DUMP, DUMP TL and DUMP VERSION (L5396-5414, L9986-9992): the drive's own listing of its program and
// variables, made to be sent back to a drive. The seed gives no line format; chosen: "NAME value" per
// variable in user units (the form L9994-10009 uploads), program lines and every variable a drive would
// refuse (protected, monitor-only) prefixed with ';' so re-sending the dump is harmless.
#pragma once

#include "bds5_interpreter.h"

#include <string>

namespace drive_core::bds5 {

inline constexpr std::string_view kFirmwareVersion = "BDS5 FIRMWARE V3.0.0 (SERVODESK SIMULATION)";

// Each returns CR LF terminated lines.
std::string dumpAll(const Bds5State& state);
std::string dumpLoopGains(const Bds5State& state); // DUMP TL: the compensation variables, with LPF/LPFHZ (v3)
std::string dumpVersion();

} // namespace drive_core::bds5
