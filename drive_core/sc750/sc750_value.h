// A ServoBASIC Plus run-time value: INTEGER (int32), FLOAT (float32, also SINGLE/DOUBLE) or STRING, and
// the QuickBASIC conversions and number formatting the VM, the drive and the protocol share.
#pragma once

#include "drive_core/catalog/sc750_catalog.h"

#include <cstdint>
#include <optional>
#include <string>
#include <variant>

namespace drive_core::sc750 {

using Value = std::variant<std::int32_t, float, std::string>;

// Number as PRINT shows it, QuickBASIC style: "-3", "5", ".5", "1.234568E+07" (no sign space).
std::string formatNumber(const Value& v);
// PRINT: a leading space for non-negative numbers and a trailing space after every number.
std::string printText(const Value& v);
// STR$: leading space for non-negative numbers, none after.
std::string strText(const Value& v);

inline double toDouble(const Value& v) { // strings: 0 (inline: the drive reads its variables every tick)
    if (const auto* i = std::get_if<std::int32_t>(&v)) return *i;
    if (const auto* f = std::get_if<float>(&v)) return *f;
    return 0;
}
// Round half to even into int32 (QuickBASIC CINT); nullopt when out of range.
std::optional<std::int32_t> toInteger(double x);
// Converts v to type; nullopt when a number does not fit an INTEGER or a string meets a number.
std::optional<Value> convert(const Value& v, catalog::sc750::ValueType type);
// VAL: leading number of the text ("12.50" -> 12.5, ".2" -> 0.2, "abc" -> 0); complete = the whole text was one.
double parseNumber(const std::string& text, bool* complete = nullptr);
// A value from protocol or Variables-window text for a variable of type (strings taken as they are).
std::optional<Value> parseValue(const std::string& text, catalog::sc750::ValueType type);

} // namespace drive_core::sc750
