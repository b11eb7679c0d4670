// Reads and writes a Capture as Motion Link's .CSV ("comma separated variables", spreadsheet compatible;
// the manual gives no layout, L1086). ServoDesk's layout, one record per line, CR LF or LF:
//   RECORD,<n>,<t ms>,<v1>[,v2,v3,v4]       the set-up as RECORD takes it: samples, interval, variables
//   Time (s),<v1> (<unit>)[,...]            column titles; the unit in parentheses, omitted when none; up to 8:
//                                           the 4 recorded and the math channels the scope shows with them
//   0,<value>[,...]                         one row per sample: time in seconds, then the values
// Reading also accepts a file without the RECORD line (the interval then comes from the time column).
// Reading parses the text in place (std::from_chars, no allocation per line): a 1,000,000-row file in
// tens of milliseconds.
#pragma once

#include "capture.h"

#include <optional>
#include <string>
#include <string_view>

namespace scope {

struct CsvReadResult {
    std::optional<Capture> capture;
    std::string error; // "line 4: 2 values, expected 3"
};

std::string writeCsv(const Capture& capture);
// The whole file's text; it need only live for the call (a QByteArray's bytes can be passed as they are).
CsvReadResult readCsv(std::string_view text);

} // namespace scope
