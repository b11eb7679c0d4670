// PLAY listing -> Capture.
#include "play_parser.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>

namespace scope {

namespace {

constexpr double kMaxPlaySamples = 1'000'000;

std::vector<std::string> words(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

std::optional<double> number(const std::string& text) {
    double value = 0;
    const char* first = text.data();
    if (!text.empty() && text.front() == '+') ++first;
    const auto [end, ec] = std::from_chars(first, text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
    return value;
}

std::string upper(std::string s) {
    for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

bool blank(const std::string& line) {
    for (const char c : line)
        if (!std::isspace(static_cast<unsigned char>(c))) return false;
    return true;
}

} // namespace

PlayParseResult parsePlay(const std::vector<std::string>& lines,
                          const std::function<std::string(const std::string&)>& unitOf) {
    PlayParseResult result;
    std::size_t at = 0;
    while (at < lines.size() && blank(lines[at])) ++at;
    if (at == lines.size()) {
        result.error = "PLAY printed nothing";
        return result;
    }
    // RECORD <n> <t> <v1> [v2 v3 v4]
    const auto head = words(lines[at]);
    const auto n = head.size() >= 4 ? number(head[1]) : std::nullopt;
    const auto t = head.size() >= 4 ? number(head[2]) : std::nullopt;
    // A count the drive could have printed: a whole number of samples (the BDS5 takes at most 1000;
    // a listing saved elsewhere may hold more, up to what a series can keep) and a finite interval.
    const bool countOk = n && *n >= 1 && *n <= kMaxPlaySamples && *n == std::floor(*n);
    const bool intervalOk = t && *t > 0;
    if (head.size() < 4 || head.size() > 7 || upper(head[0]) != "RECORD" || !countOk || !intervalOk) {
        result.error =
            "line " + std::to_string(at + 1) + ": expected \"RECORD <n> <t> <variables>\", found \"" + lines[at] + "\"";
        return result;
    }
    Capture capture;
    capture.interval_s = *t / 1000.0;
    result.requestedSamples = int(*n);
    for (std::size_t i = 3; i < head.size(); ++i) {
        const std::string name = upper(head[i]);
        capture.channels.push_back({name, unitOf ? unitOf(name) : std::string(), {}});
    }
    for (++at; at < lines.size(); ++at) {
        if (blank(lines[at])) continue;
        const auto values = words(lines[at]);
        if (values.size() != capture.channels.size()) {
            result.error = "line " + std::to_string(at + 1) + ": " + std::to_string(values.size()) +
                           " values, expected " + std::to_string(capture.channels.size());
            return result;
        }
        for (std::size_t c = 0; c < values.size(); ++c) {
            const auto v = number(values[c]);
            if (!v) {
                result.error = "line " + std::to_string(at + 1) + ": \"" + values[c] + "\" is not a number";
                return result;
            }
            capture.channels[c].values.push_back(*v);
        }
    }
    result.capture = std::move(capture);
    return result;
}

} // namespace scope
