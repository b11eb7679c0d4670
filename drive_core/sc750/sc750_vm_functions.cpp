// The ServoBASIC Plus built-in functions (L1238-L1297) and the Variables-window access to user variables.
// QuickBASIC semantics, with the manual's deviations: LTRIM$ trims both ends (L1282), ASC("") is 0.
#include "sc750_vm.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

namespace drive_core::sc750 {

namespace cat = catalog::sc750;

Value Vm::callFunction(int index, int argc) {
    std::vector<Value> a(static_cast<std::size_t>(argc));
    for (int i = argc - 1; i >= 0; --i) a[std::size_t(i)] = pop();
    const std::string_view name = cat::functions()[std::size_t(index)].name;
    auto num = [&](std::size_t i) { return toDouble(a[i]); };
    auto integer = [&](std::size_t i) { return toInteger(num(i)).value_or(0); };
    static const std::string kEmpty;
    auto str = [&](std::size_t i) -> const std::string& { // only a damaged .BIN passes a number here
        const auto* s = std::get_if<std::string>(&a[i]);
        return s ? *s : kEmpty;
    };
    auto illegal = [&]() {
        runtimeError("ILLEGAL FUNCTION CALL " + std::string(name));
        return Value(std::int32_t(0));
    };
    auto real = [&](double x) -> Value {
        if (!std::isfinite(x)) return illegal();
        return float(x);
    };
    if (name == "ABS") {
        if (std::holds_alternative<std::int32_t>(a[0])) return std::int32_t(std::abs(std::get<std::int32_t>(a[0])));
        return real(std::fabs(num(0)));
    }
    if (name == "ATAN") return real(std::atan(num(0)));
    if (name == "COS") return real(std::cos(num(0)));
    if (name == "SIN") return real(std::sin(num(0)));
    if (name == "TAN") return real(std::tan(num(0)));
    if (name == "SQR") return num(0) < 0 ? illegal() : real(std::sqrt(num(0)));
    if (name == "LOG") return num(0) <= 0 ? illegal() : real(std::log(num(0)));
    if (name == "LOG10") return num(0) <= 0 ? illegal() : real(std::log10(num(0)));
    if (name == "CINT" || name == "FIX" || name == "INT") {
        const double x = name == "CINT" ? num(0) : name == "FIX" ? std::trunc(num(0)) : std::floor(num(0));
        const auto i = toInteger(x);
        if (!i) return illegal();
        return *i;
    }
    if (name == "SGN") return std::int32_t(num(0) > 0 ? 1 : num(0) < 0 ? -1 : 0);
    if (name == "ASC") return std::int32_t(str(0).empty() ? 0 : static_cast<unsigned char>(str(0)[0]));
    if (name == "CHR$") {
        const int code = integer(0);
        if (code < 0 || code > 255) return illegal();
        return std::string(1, char(code));
    }
    if (name == "HEX$") {
        char buffer[16];
        std::snprintf(buffer, sizeof buffer, "%X", static_cast<unsigned>(integer(0)));
        return std::string(buffer);
    }
    if (name == "INKEY$") return m_host.takeChar();
    if (name == "INSTR") {
        const std::size_t base = argc == 3 ? 1 : 0;
        const int start = argc == 3 ? integer(0) : 1;
        if (start < 1) return illegal();
        const std::string& s = str(base);
        const std::string& find = str(base + 1);
        if (std::size_t(start) > s.size() + 1) return std::int32_t(0);
        const auto at = s.find(find, std::size_t(start - 1));
        return std::int32_t(at == std::string::npos ? 0 : int(at) + 1);
    }
    if (name == "LCASE$" || name == "UCASE$") {
        std::string s = str(0);
        for (char& c : s)
            c = char(name == "LCASE$" ? std::tolower(static_cast<unsigned char>(c))
                                      : std::toupper(static_cast<unsigned char>(c)));
        return s;
    }
    if (name == "LEFT$" || name == "RIGHT$") {
        const int n = integer(1);
        if (n < 0) return illegal();
        const std::string& s = str(0);
        const std::size_t k = std::min(std::size_t(n), s.size());
        return name == "LEFT$" ? s.substr(0, k) : s.substr(s.size() - k);
    }
    if (name == "LEN") return std::int32_t(str(0).size());
    if (name == "LTRIM$") {
        std::string s = str(0);
        const auto first = s.find_first_not_of(' ');
        if (first == std::string::npos) return std::string();
        return s.substr(first, s.find_last_not_of(' ') - first + 1);
    }
    if (name == "MID$") {
        const int start = integer(1);
        const int n = argc == 3 ? integer(2) : 1 << 30;
        if (start < 1 || n < 0) return illegal();
        const std::string& s = str(0);
        if (std::size_t(start) > s.size()) return std::string();
        return s.substr(std::size_t(start - 1), std::size_t(n));
    }
    if (name == "SPACE$" || name == "STRING$") {
        const int n = integer(0);
        if (n < 0 || n > kMaxStringLength) return illegal();
        char c = ' ';
        if (name == "STRING$") {
            if (const auto* s = std::get_if<std::string>(&a[1])) {
                if (s->empty()) return illegal();
                c = (*s)[0];
            } else {
                const int code = integer(1);
                if (code < 0 || code > 255) return illegal();
                c = char(code);
            }
        }
        return std::string(std::size_t(n), c);
    }
    if (name == "STR$") return strText(a[0]);
    if (name == "VAL") return float(parseNumber(str(0)));
    return illegal();
}

int Vm::findVariable(const std::string& upperName) const {
    if (!m_program) return -1;
    for (std::size_t i = 0; i < m_program->variables.size(); ++i)
        if (m_program->variables[i].name == upperName) return int(i);
    return -1;
}

std::optional<Value> Vm::variable(int index, int element) const {
    if (index < 0 || std::size_t(index) >= m_vars.size()) return std::nullopt;
    const auto& v = m_vars[std::size_t(index)];
    if (element < 0 || std::size_t(element) >= v.size()) return std::nullopt;
    return v[std::size_t(element)];
}

bool Vm::setVariable(int index, int element, const Value& value) {
    if (index < 0 || std::size_t(index) >= m_vars.size()) return false;
    auto& v = m_vars[std::size_t(index)];
    if (element < 0 || std::size_t(element) >= v.size()) return false;
    const auto converted = convert(value, m_program->variables[std::size_t(index)].type);
    if (!converted) return false;
    v[std::size_t(element)] = *converted;
    return true;
}

} // namespace drive_core::sc750
