// Parses the BDS5's PLAY listing into a Capture: a first line repeating the set-up
// ("RECORD <n> <t> <v1> [v2 v3 v4]") then one line per sample with one 12-column value per variable
// (drive_core/bds5/bds5_recorder.h). The manual does not print the format; values are read as
// whitespace-separated numbers, so a listing with other column widths still parses.
#pragma once

#include "capture.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace scope {

struct PlayParseResult {
    std::optional<Capture> capture; // set when the listing was understood
    std::string error;              // why not, naming the line ("line 3: 2 values, expected 3")
    int requestedSamples = 0;       // <n> of the RECORD line (the capture may hold fewer if PLAY came early)
};

// lines: PLAY's output lines without CR LF (blank lines are skipped). unitOf names each variable's unit.
PlayParseResult parsePlay(const std::vector<std::string>& lines,
                          const std::function<std::string(const std::string&)>& unitOf = {});

} // namespace scope
