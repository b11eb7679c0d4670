// .CSV layout of a Capture, written and read.
#include "capture_csv.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <vector>

namespace scope {

namespace {

std::string format(double value) {
    char buffer[64];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    return ec == std::errc() ? std::string(buffer, end) : std::string("0");
}

// Blanks, control characters and quotes around a field are not part of it (one set for both ends:
// capture_files_fuzz found "  \r " kept as a name that could not be read back).
bool kept(char c) {
    return static_cast<unsigned char>(c) > ' ' && c != '"';
}

std::string_view trimmed(std::string_view field) {
    std::size_t first = 0;
    std::size_t last = field.size();
    while (first < last && !kept(field[first])) ++first;
    while (last > first && !kept(field[last - 1])) --last;
    return field.substr(first, last - first);
}

// A line's fields: one more than its commas (a last, empty field after a final comma included).
std::vector<std::string> fields(std::string_view line) {
    std::vector<std::string> out;
    for (std::size_t start = 0;;) {
        const std::size_t comma = line.find(',', start);
        out.emplace_back(trimmed(line.substr(start, comma == std::string_view::npos ? comma : comma - start)));
        if (comma == std::string_view::npos) return out;
        start = comma + 1;
    }
}

// A decimal number as std::from_chars reads it, with an optional '+' before it, and nothing after it.
std::optional<double> number(std::string_view text) {
    double value = 0;
    const char* first = text.data();
    const char* const last = text.data() + text.size();
    if (!text.empty() && text.front() == '+') ++first;
    const auto [end, ec] = std::from_chars(first, last, value);
    if (ec != std::errc() || end != last) return std::nullopt;
    return value;
}

// The end of a plain decimal at p ("-12.5", "0.001", "7."), or nullptr for anything else (a leading '.',
// an exponent is left at the 'e'). Every such text of up to 30 characters is one std::from_chars reads
// whole and in range: the time column is checked this way, its values past the first two being unused.
const char* plainDecimalEnd(const char* p, const char* end) {
    const char* const start = p;
    if (p != end && *p == '-') ++p;
    const char* const digits = p;
    while (p != end && static_cast<unsigned>(*p - '0') < 10) ++p;
    if (p == digits) return nullptr;
    if (p != end && *p == '.')
        for (++p; p != end && static_cast<unsigned>(*p - '0') < 10;) ++p;
    return p - start <= 30 ? p : nullptr;
}

// The text's lines as std::getline splits them at LF (none after a final LF), each without one CR at its end.
class Lines {
public:
    explicit Lines(std::string_view text) : m_text(text) {}
    bool next(std::string_view& line) {
        if (m_at >= m_text.size()) return false;
        const std::size_t lf = m_text.find('\n', m_at);
        const std::size_t end = lf == std::string_view::npos ? m_text.size() : lf;
        line = m_text.substr(m_at, end - m_at);
        m_at = end + 1;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        return true;
    }
    std::string_view rest() const { return m_text.substr(std::min(m_at, m_text.size())); }

    // The common row, plain numbers between commas ("0.001,-12.5\r\n", a '+' allowed), read straight from
    // the text: true with row[0, columns) set and the row consumed. Any other row (blanks, quotes, a wrong
    // count, not a number) is left for next() and the field-by-field reading, which gives the same values
    // for a plain row: a number never holds a ',', CR or LF, so from_chars stops where the field ends.
    // Without needTime, a plain decimal time is only checked, not converted (row[0] is then not set).
    bool plainRow(std::size_t columns, double* row, bool needTime) {
        const char* p = m_text.data() + m_at;
        const char* const end = m_text.data() + m_text.size();
        if (m_at >= m_text.size()) return false;
        for (std::size_t c = 0; c < columns; ++c) {
            if (p == end || !kept(*p)) return false;
            const char* const first = *p == '+' ? p + 1 : p;
            if (const char* stop = c == 0 && !needTime ? plainDecimalEnd(first, end) : nullptr) {
                p = stop;
            } else {
                const auto [stop2, ec] = std::from_chars(first, end, row[c]);
                if (ec != std::errc()) return false;
                p = stop2;
            }
            if (c + 1 < columns && (p == end || *p++ != ',')) return false;
        }
        if (p != end && *p == '\r') ++p; // the one CR next() would take off
        if (p != end && *p++ != '\n') return false;
        m_at = std::size_t(p - m_text.data());
        return true;
    }

private:
    std::string_view m_text;
    std::size_t m_at = 0;
};

// Rows to reserve: the bytes left over the first row's length, a quarter to spare for longer rows; never
// more than the bytes could hold (a row has at least two bytes a column).
std::size_t expectedRows(std::string_view rest, std::size_t columns) {
    const std::size_t lf = rest.find('\n');
    const std::size_t rowBytes = std::max<std::size_t>(lf == std::string_view::npos ? rest.size() : lf + 1, 1);
    return std::min(rest.size() / rowBytes * 5 / 4 + 16, rest.size() / (2 * columns) + 1);
}

// "VFB (VEL)" -> {"VFB", "VEL"}; "X1" -> {"X1", ""}. The name ends at its last kept character: "V   ()"
// is "V" with no unit, as written back it is read (capture_files_fuzz found "V  " kept as the name).
CaptureChannel channelFromTitle(const std::string& title) {
    const auto open = title.find(" (");
    if (open == std::string::npos || title.back() != ')') return {title, "", {}};
    const std::string_view name = trimmed(std::string_view(title).substr(0, open));
    return {std::string(name), title.substr(open + 2, title.size() - open - 3), {}};
}

// A time to the microsecond, the resolution the file keeps. Rounding is a fixed point only while t·1e6 has
// digits after its point: past 2^53 µs (~285 years) it is an integer already and dividing it again moves
// the time, so a file read and written again would change (capture_files_fuzz finding); such times stay.
double toMicroseconds(double t_s) {
    return std::fabs(t_s) < 1e9 ? std::round(t_s * 1e6) / 1e6 : t_s;
}

// The interval the file states: RECORD gives it in ms and a reader divides by 1000, and x * 1000 / 1000 is
// not always x, so a file read and written again could move every row's time in its last digit (a
// capture_files_fuzz finding). The writer steps to an interval that survives that, usually at once.
double writtenInterval(double interval_s) {
    double x = interval_s;
    for (int step = 0; step < 8 && std::isfinite(x); ++step) {
        const double back = x * 1000.0 / 1000.0;
        if (back == x) break;
        x = back;
    }
    return x;
}

} // namespace

std::string writeCsv(const Capture& capture) {
    const double interval_s = writtenInterval(capture.interval_s);
    std::string out = "RECORD," + std::to_string(capture.sampleCount()) + "," + format(interval_s * 1000.0);
    for (const CaptureChannel& c : capture.channels) out += "," + c.name;
    out += "\r\nTime (s)";
    for (const CaptureChannel& c : capture.channels) out += "," + c.name + (c.unit.empty() ? "" : " (" + c.unit + ")");
    out += "\r\n";
    for (std::size_t i = 0; i < capture.sampleCount(); ++i) {
        out += format(toMicroseconds(capture.start_s + double(i) * interval_s));
        for (const CaptureChannel& c : capture.channels) out += "," + format(c.values[i]);
        out += "\r\n";
    }
    return out;
}

constexpr std::size_t kMaxVariables = 8;

CsvReadResult readCsv(std::string_view text) {
    CsvReadResult result;
    Lines lines(text);
    std::string_view line;
    bool more = lines.next(line);
    std::size_t at = 0; // index of `line`: errors name line at + 1
    auto fail = [&result](std::size_t index, const std::string& why) {
        result.error = "line " + std::to_string(index + 1) + ": " + why;
        return result;
    };
    Capture capture;
    std::optional<double> intervalMs;
    if (more) {
        const auto record = fields(line);
        if (record.size() >= 3 && record[0] == "RECORD") {
            intervalMs = number(record[2]);
            if (!intervalMs || *intervalMs <= 0) return fail(at, "the RECORD line has no interval in ms");
            ++at;
            more = lines.next(line);
        }
    }
    if (!more) return fail(at, "no column titles");
    const auto titles = fields(line);
    // Up to 8 variables: a RECORD's 4 and the math channels the scope adds to them (its plot shows 8).
    if (titles.size() < 2 || titles.size() > kMaxVariables + 1)
        return fail(at, "expected a time column and 1 to " + std::to_string(kMaxVariables) + " variables");
    for (std::size_t c = 1; c < titles.size(); ++c) {
        capture.channels.push_back(channelFromTitle(titles[c]));
        // A column without a name could not be told apart from a stray comma (capture_files_fuzz finding).
        if (capture.channels.back().name.empty())
            return fail(at, "column " + std::to_string(c + 1) + " has no variable name");
    }
    const std::size_t columns = titles.size();
    const std::size_t rows = expectedRows(lines.rest(), columns);
    for (CaptureChannel& c : capture.channels) c.values.reserve(rows);
    // Rows are parsed where they lie: each field trimmed and read in place, nothing allocated per line.
    double firstTimes[2] = {0, 0};
    std::size_t timesSeen = 0;
    double row[kMaxVariables + 1];
    const auto keep = [&](const double* values) {
        if (timesSeen < 2) firstTimes[timesSeen++] = values[0];
        for (std::size_t c = 1; c < columns; ++c) capture.channels[c - 1].values.push_back(values[c]);
    };
    for (++at;; ++at) {
        if (lines.plainRow(columns, row, timesSeen < 2)) {
            keep(row);
            continue;
        }
        if (!lines.next(line)) break;
        if (line.find_first_not_of(" \t,") == std::string_view::npos) continue;
        std::size_t count = 0;
        std::string_view bad; // the first field that is not a number, when the count is right
        bool failed = false;
        for (std::size_t start = 0;;) {
            const std::size_t comma = line.find(',', start);
            if (count < columns && !failed) {
                const std::string_view field =
                    trimmed(line.substr(start, comma == std::string_view::npos ? comma : comma - start));
                if (const auto v = number(field)) {
                    row[count] = *v;
                } else {
                    failed = true;
                    bad = field;
                }
            }
            ++count;
            if (comma == std::string_view::npos) break;
            start = comma + 1;
        }
        if (count != columns) return fail(at, std::to_string(count) + " values, expected " + std::to_string(columns));
        if (failed) return fail(at, "\"" + std::string(bad) + "\" is not a number");
        keep(row);
    }
    // The first time is where the record starts (a slice of a longer one starts later), to the microsecond
    // writeCsv keeps, so that a file read and written again gives the same text.
    if (timesSeen >= 1) {
        const double start = toMicroseconds(firstTimes[0]);
        if (std::isfinite(start)) capture.start_s = start;
    }
    if (intervalMs)
        capture.interval_s = *intervalMs / 1000.0;
    else if (timesSeen >= 2 && firstTimes[1] > firstTimes[0])
        capture.interval_s = firstTimes[1] - firstTimes[0];
    result.capture = std::move(capture);
    return result;
}

} // namespace scope
