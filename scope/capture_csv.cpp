// .CSV layout of a Capture, written and read.
#include "capture_csv.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>
#include <vector>

namespace scope {

namespace {

std::string format(double value) {
    char buffer[64];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    return ec == std::errc() ? std::string(buffer, end) : std::string("0");
}

std::vector<std::string> fields(const std::string& line) {
    std::vector<std::string> out;
    std::string field;
    std::istringstream in(line);
    while (std::getline(in, field, ',')) {
        // Blanks, control characters and quotes around a field are not part of it (one set for both ends:
        // capture_files_fuzz found "  \r " kept as a name that could not be read back).
        const auto kept = [](char c) { return static_cast<unsigned char>(c) > ' ' && c != '"'; };
        const auto first = std::find_if(field.begin(), field.end(), kept);
        const auto last = std::find_if(field.rbegin(), field.rend(), kept).base();
        out.push_back(first < last ? std::string(first, last) : std::string());
    }
    if (!line.empty() && line.back() == ',') out.emplace_back(); // getline drops a last, empty field
    return out;
}

std::optional<double> number(const std::string& text) {
    double value = 0;
    const char* first = text.data();
    if (!text.empty() && text.front() == '+') ++first;
    const auto [end, ec] = std::from_chars(first, text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return value;
}

// "VFB (VEL)" -> {"VFB", "VEL"}; "X1" -> {"X1", ""}.
CaptureChannel channelFromTitle(const std::string& title) {
    const auto open = title.find(" (");
    if (open == std::string::npos || title.back() != ')') return {title, "", {}};
    return {title.substr(0, open), title.substr(open + 2, title.size() - open - 3), {}};
}

} // namespace

std::string writeCsv(const Capture& capture) {
    std::string out = "RECORD," + std::to_string(capture.sampleCount()) + "," + format(capture.interval_s * 1000.0);
    for (const CaptureChannel& c : capture.channels) out += "," + c.name;
    out += "\r\nTime (s)";
    for (const CaptureChannel& c : capture.channels) out += "," + c.name + (c.unit.empty() ? "" : " (" + c.unit + ")");
    out += "\r\n";
    for (std::size_t i = 0; i < capture.sampleCount(); ++i) {
        out += format(std::round(capture.timeAt(i) * 1e6) / 1e6);
        for (const CaptureChannel& c : capture.channels) out += "," + format(c.values[i]);
        out += "\r\n";
    }
    return out;
}

CsvReadResult readCsv(const std::string& text) {
    CsvReadResult result;
    std::istringstream in(text);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        lines.push_back(line);
    }
    std::size_t at = 0;
    auto fail = [&result](std::size_t line, const std::string& why) {
        result.error = "line " + std::to_string(line + 1) + ": " + why;
        return result;
    };
    Capture capture;
    std::optional<double> intervalMs;
    if (at < lines.size() && fields(lines[at]).size() >= 3 && fields(lines[at])[0] == "RECORD") {
        intervalMs = number(fields(lines[at])[2]);
        if (!intervalMs || *intervalMs <= 0) return fail(at, "the RECORD line has no interval in ms");
        ++at;
    }
    if (at >= lines.size()) return fail(at, "no column titles");
    const auto titles = fields(lines[at]);
    if (titles.size() < 2 || titles.size() > 5) return fail(at, "expected a time column and 1 to 4 variables");
    for (std::size_t c = 1; c < titles.size(); ++c) {
        capture.channels.push_back(channelFromTitle(titles[c]));
        // A column without a name could not be told apart from a stray comma (capture_files_fuzz finding).
        if (capture.channels.back().name.empty())
            return fail(at, "column " + std::to_string(c + 1) + " has no variable name");
    }
    std::vector<double> times;
    for (++at; at < lines.size(); ++at) {
        if (lines[at].find_first_not_of(" \t,") == std::string::npos) continue;
        const auto row = fields(lines[at]);
        if (row.size() != titles.size())
            return fail(at, std::to_string(row.size()) + " values, expected " + std::to_string(titles.size()));
        for (std::size_t c = 0; c < row.size(); ++c) {
            const auto v = number(row[c]);
            if (!v) return fail(at, "\"" + row[c] + "\" is not a number");
            if (c == 0)
                times.push_back(*v);
            else
                capture.channels[c - 1].values.push_back(*v);
        }
    }
    if (intervalMs)
        capture.interval_s = *intervalMs / 1000.0;
    else if (times.size() >= 2 && times[1] > times[0])
        capture.interval_s = times[1] - times[0];
    result.capture = std::move(capture);
    return result;
}

} // namespace scope
