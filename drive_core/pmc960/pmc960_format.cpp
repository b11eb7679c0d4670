// Number formats of the PMC-960 serial line (THC bits 7-6).
#include "pmc960_format.h"

namespace drive_core::pmc960 {

NumberFormat Pmc960Format::input() const {
    switch (m_thc >> 6) {
    case 3: return NumberFormat::Binary;
    case 2:
    case 1: return NumberFormat::Hex;
    default: return NumberFormat::Decimal;
    }
}

NumberFormat Pmc960Format::output() const {
    switch (m_thc >> 6) {
    case 3:
    case 2: return NumberFormat::Binary;
    case 1: return NumberFormat::Hex;
    default: return NumberFormat::Decimal;
    }
}

std::string Pmc960Format::hexDigits(std::int64_t value, int digits) {
    static constexpr char kHex[] = "0123456789ABCDEF";
    std::string out(std::size_t(digits), '0');
    auto bits = std::uint64_t(value);
    for (int i = digits - 1; i >= 0; --i) {
        out[std::size_t(i)] = kHex[bits & 0xF];
        bits >>= 4;
    }
    return out;
}

static std::string binaryBytes(std::int64_t value, int bytes) {
    std::string out;
    for (int i = bytes - 1; i >= 0; --i) {
        const char b = char((std::uint64_t(value) >> (8 * i)) & 0xFF);
        out += b;
        if (b == '#') out += b;
    }
    return out;
}

std::string Pmc960Format::number(std::int64_t value, int bits) const {
    switch (output()) {
    case NumberFormat::Decimal: return std::to_string(value);
    case NumberFormat::Hex: return hexDigits(value, bits / 4);
    case NumberFormat::Binary: return binaryBytes(value, bits / 8);
    }
    return {};
}

std::string Pmc960Format::hex(std::int64_t value, int digits) const {
    if (output() == NumberFormat::Binary) return binaryBytes(value, (digits + 1) / 2);
    return hexDigits(value, digits);
}

std::string Pmc960Format::escaped(std::string bytes) const {
    if (output() != NumberFormat::Binary) return bytes;
    std::string out;
    for (const char c : bytes) {
        out += c;
        if (c == '#') out += c;
    }
    return out;
}

} // namespace drive_core::pmc960
