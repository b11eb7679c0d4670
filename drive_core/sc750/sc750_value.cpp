// QuickBASIC conversions and number formatting for ServoBASIC Plus values.
#include "sc750_value.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace drive_core::sc750 {

using catalog::sc750::ValueType;

std::string formatNumber(const Value& v) {
    if (const auto* i = std::get_if<std::int32_t>(&v)) return std::to_string(*i);
    if (const auto* s = std::get_if<std::string>(&v)) return *s;
    const float f = std::get<float>(v);
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.7G", double(f)); // single precision: 7 significant digits
    std::string text(buffer);
    const auto e = text.find('E');
    std::string mantissa = e == std::string::npos ? text : text.substr(0, e);
    std::string exponent = e == std::string::npos ? "" : text.substr(e);
    if (mantissa.find('.') != std::string::npos) {
        while (!mantissa.empty() && mantissa.back() == '0') mantissa.pop_back();
        if (!mantissa.empty() && mantissa.back() == '.') mantissa.pop_back();
    }
    if (mantissa.rfind("0.", 0) == 0)
        mantissa.erase(0, 1); // QuickBASIC prints .5
    else if (mantissa.rfind("-0.", 0) == 0)
        mantissa.erase(1, 1); // and -.5
    return mantissa + exponent;
}

std::string strText(const Value& v) {
    if (std::holds_alternative<std::string>(v)) return std::get<std::string>(v);
    const std::string n = formatNumber(v);
    return n[0] == '-' ? n : " " + n;
}

std::string printText(const Value& v) {
    if (std::holds_alternative<std::string>(v)) return std::get<std::string>(v);
    return strText(v) + " ";
}

std::optional<std::int32_t> toInteger(double x) {
    if (!std::isfinite(x)) return std::nullopt;
    const double r = std::nearbyint(x); // the default rounding mode: half to even
    if (r > 2147483647.0 || r < -2147483648.0) return std::nullopt;
    return std::int32_t(r);
}

std::optional<Value> convert(const Value& v, ValueType type) {
    const bool isString = std::holds_alternative<std::string>(v);
    if ((type == ValueType::String) != isString) return std::nullopt;
    if (type == ValueType::String) return v;
    if (type == ValueType::Float) return Value(float(toDouble(v)));
    if (const auto* i = std::get_if<std::int32_t>(&v)) return Value(*i);
    const auto i = toInteger(toDouble(v));
    if (!i) return std::nullopt;
    return Value(*i);
}

double parseNumber(const std::string& text, bool* complete) {
    std::size_t begin = 0;
    while (begin < text.size() && text[begin] == ' ') ++begin;
    const char* start = text.c_str() + begin;
    char* end = nullptr;
    const double value = std::strtod(start, &end);
    if (end == start) {
        if (complete) *complete = false;
        return 0;
    }
    if (complete) {
        const char* p = end;
        while (*p == ' ') ++p;
        *complete = *p == '\0';
    }
    return value;
}

std::optional<Value> parseValue(const std::string& text, ValueType type) {
    if (type == ValueType::String) return Value(text);
    bool complete = false;
    const double x = parseNumber(text, &complete);
    if (!complete) return std::nullopt;
    if (type == ValueType::Integer) {
        const auto i = toInteger(x);
        if (!i) return std::nullopt;
        return Value(*i);
    }
    return Value(float(x));
}

} // namespace drive_core::sc750
