// Reads and writes a Capture as Motion Link's .CSV ("comma separated variables", spreadsheet compatible;
// the manual gives no layout, L1086). ServoDesk's layout, one record per line, CR LF or LF:
//   RECORD,<n>,<t ms>,<v1>[,v2,v3,v4]       the set-up as RECORD takes it: samples, interval, variables
//   Time (s),<v1> (<unit>)[,...]            column titles; the unit in parentheses, omitted when none
//   0,<value>[,...]                         one row per sample: time in seconds, then the values
// Reading also accepts a file without the RECORD line (the interval then comes from the time column).
#pragma once

#include "capture.h"

#include <optional>
#include <string>

namespace scope {

struct CsvReadResult {
    std::optional<Capture> capture;
    std::string error; // "line 4: 2 values, expected 3"
};

std::string writeCsv(const Capture& capture);
CsvReadResult readCsv(const std::string& text);

} // namespace scope
