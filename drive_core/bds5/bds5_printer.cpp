// BDS5 print formatting.
#include "bds5_printer.h"

#include <cctype>
#include <charconv>
#include <cstdlib>

namespace drive_core::bds5 {

namespace {

constexpr int kDefaultWidth = 12; // L9650, L4207
constexpr int kHexWidth = 9;      // 8 digits + 'H' (L4265)

// Right-justifies in width; a number that does not fit fills the field with 'X' (VFB[3] -> XXX).
std::string fit(const std::string& digits, int width) {
    if (width <= 0) return digits;
    if (int(digits.size()) > width) return std::string(std::size_t(width), 'X');
    return std::string(std::size_t(width) - digits.size(), ' ') + digits;
}

std::optional<int> number(std::string_view s) {
    if (s.empty()) return std::nullopt;
    int v = 0;
    const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc{} || ptr != s.data() + s.size() || v < 0 || v > 80) return std::nullopt;
    return v;
}

std::string decimal(std::int32_t value, int point, int printable) {
    const bool negative = value < 0;
    std::string digits = std::to_string(std::llabs(std::int64_t(value)));
    if (point > 0) {
        if (int(digits.size()) <= point) digits.insert(0, std::size_t(point + 1) - digits.size(), '0');
        std::string whole = digits.substr(0, digits.size() - std::size_t(point));
        std::string frac = digits.substr(digits.size() - std::size_t(point));
        frac.resize(std::size_t(std::min(printable, point))); // truncated, not rounded (L4250)
        digits = frac.empty() ? whole : whole + "." + frac;
    }
    return negative ? "-" + digits : digits;
}

std::string hex(std::int32_t value) {
    static const char* kDigits = "0123456789ABCDEF";
    auto u = static_cast<std::uint32_t>(value);
    std::string out;
    do {
        out.insert(out.begin(), kDigits[u & 0xF]);
        u >>= 4;
    } while (u != 0);
    return out + "H";
}

std::string binary(std::int32_t value) {
    auto u = static_cast<std::uint32_t>(value);
    std::string out;
    do {
        out.insert(out.begin(), char('0' + (u & 1)));
        u >>= 1;
    } while (u != 0);
    return out;
}

// Four bytes, most significant first; bit 7 stripped; zero bytes are not printed (L4316-4331).
std::string characters(std::int32_t value) {
    auto u = static_cast<std::uint32_t>(value);
    std::string out;
    for (int shift = 24; shift >= 0; shift -= 8) {
        const char c = char((u >> shift) & 0x7F);
        if (c != 0) out.push_back(c);
    }
    return out;
}

} // namespace

std::optional<std::string> formatValue(std::int32_t value, std::string_view format) {
    if (format.empty()) return fit(std::to_string(value), kDefaultWidth);
    const char kind = char(std::toupper(static_cast<unsigned char>(format.front())));
    const char last = char(std::toupper(static_cast<unsigned char>(format.back())));
    // Letter formats take an optional width before or after the letter: [H], [5H], [H5] (L6979, L4265).
    for (const char letter : {'H', 'C', 'B', 'S'}) {
        if (kind != letter && last != letter) continue;
        std::string_view w = kind == letter ? format.substr(1) : format.substr(0, format.size() - 1);
        std::optional<int> width = w.empty() ? std::optional<int>(0) : number(w);
        if (!width) return std::nullopt;
        switch (letter) {
        case 'H': return fit(hex(value), *width ? *width : kHexWidth);
        case 'C': return *width ? fit(characters(value), *width) : characters(value);
        case 'B': return fit(binary(value), *width); // width of [B] is not in the seed: as wide as needed
        default: return fit(value ? "ON" : "OFF", *width ? *width : 3);
        }
    }
    // [w.d.p] — any part may be omitted; width 12, point 0, printable = point by default.
    std::string_view parts[3];
    int count = 0;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= format.size(); ++i) {
        if (i == format.size() || format[i] == '.') {
            if (count == 3) return std::nullopt;
            parts[count++] = format.substr(start, i - start);
            start = i + 1;
        }
    }
    const auto width = parts[0].empty() ? std::optional<int>(kDefaultWidth) : number(parts[0]);
    const auto point = count < 2 || parts[1].empty() ? std::optional<int>(0) : number(parts[1]);
    if (!width || !point || *point > 10) return std::nullopt;
    const auto printable = count < 3 || parts[2].empty() ? std::optional<int>(*point) : number(parts[2]);
    if (!printable) return std::nullopt;
    return fit(decimal(value, *point, *printable), *width);
}

std::string expandControlCharacters(std::string_view text) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '^' && i + 1 < text.size()) {
            const char n = char(std::toupper(static_cast<unsigned char>(text[i + 1])));
            if ((n >= 'A' && n <= 'Z') || n == '[' || n == '\\' || n == ']' || n == '^' || n == '_') {
                out.push_back(char(n - '@'));
                ++i;
                continue;
            }
            if (n == '/') { // the manual prints ^\ as ^/ (L4323)
                out.push_back('\x1c');
                ++i;
                continue;
            }
        }
        out.push_back(c);
    }
    return out;
}

} // namespace drive_core::bds5
