// Look-ups over the BDS5 catalog tables (the tables themselves live in bds5_errors/commands/variables.cpp).
#include "bds5_catalog.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <unordered_map>
#include <vector>

namespace drive_core::catalog::bds5 {

// findError and findCommand run for every line a terminal or a program sends (the answer, the command's
// legal modes), so both tables are indexed once: errors by number, commands by name. A name or number the
// tables repeat resolves to its first entry, as a search from the front would.
const ErrorInfo* findError(int code) {
    static const std::vector<const ErrorInfo*> kByCode = [] {
        std::vector<const ErrorInfo*> byCode;
        for (const ErrorInfo& e : errors()) {
            if (e.code < 0) continue;
            if (std::size_t(e.code) >= byCode.size()) byCode.resize(std::size_t(e.code) + 1, nullptr);
            if (!byCode[std::size_t(e.code)]) byCode[std::size_t(e.code)] = &e;
        }
        return byCode;
    }();
    return code >= 0 && std::size_t(code) < kByCode.size() ? kByCode[std::size_t(code)] : nullptr;
}

const CommandInfo* findCommand(std::string_view upperName) {
    static const std::unordered_map<std::string_view, const CommandInfo*> kByName = [] {
        std::unordered_map<std::string_view, const CommandInfo*> byName;
        for (const CommandInfo& c : commands()) byName.emplace(c.name, &c);
        return byName;
    }();
    const auto it = kByName.find(upperName);
    return it == kByName.end() ? nullptr : it->second;
}

namespace {
// findVariable runs for every switch the drive consults (ECHO per received byte, SERIAL and TMR1-4 per
// step, MULTI per program line), so the catalog is indexed once: plain names in a hash map, the
// indexed families (X, XS, I, O, TMR, ...) in a short list, longest stem first.
struct VariableIndex {
    std::unordered_map<std::string_view, const VariableInfo*> plain;
    std::vector<const VariableInfo*> families;

    VariableIndex() {
        for (const VariableInfo& v : variables()) {
            if (v.firstIndex == 0)
                plain.emplace(v.name, &v); // a repeated name: the first one wins
            else
                families.push_back(&v);
        }
        std::stable_sort(families.begin(), families.end(),
                         [](const VariableInfo* a, const VariableInfo* b) { return a->name.size() > b->name.size(); });
    }
};
} // namespace

std::optional<VariableRef> findVariable(std::string_view upperName) {
    static const VariableIndex kIndex;
    // Plain names first: "XS" is not X with index "S", and "TMR1" must not match a plain "TMR".
    if (const auto it = kIndex.plain.find(upperName); it != kIndex.plain.end()) return VariableRef{it->second, 0};
    // Indexed families: the longest stem followed by a decimal index in range, so the name ends in a digit
    // (most words typed that are not a variable do not: they are answered without trying every stem).
    if (upperName.empty() || !std::isdigit(static_cast<unsigned char>(upperName.back()))) return std::nullopt;
    for (const VariableInfo* v : kIndex.families) {
        if (!upperName.starts_with(v->name)) continue;
        const std::string_view digits = upperName.substr(v->name.size());
        if (digits.empty() || digits.front() == '0' || !std::all_of(digits.begin(), digits.end(), [](char c) {
                return std::isdigit(static_cast<unsigned char>(c));
            }))
            continue;
        int index = 0;
        const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), index);
        if (ec != std::errc{} || index < v->firstIndex || index > highestIndex(*v)) continue;
        return VariableRef{v, index};
    }
    return std::nullopt;
}

std::int64_t minimumOf(const VariableInfo& v) {
    switch (v.limits) {
    case LimitClass::Long: return INT32_MIN;
    case LimitClass::LongPositive: return 0;
    case LimitClass::Short: return -32768;
    case LimitClass::ShortPositive: return 0;
    case LimitClass::Switch: return 0;
    case LimitClass::Range: return v.minimum;
    case LimitClass::None: return INT32_MIN;
    }
    return INT32_MIN;
}

std::int64_t maximumOf(const VariableInfo& v) {
    switch (v.limits) {
    case LimitClass::Long: return INT32_MAX;
    case LimitClass::LongPositive: return INT32_MAX;
    case LimitClass::Short: return 32767;
    case LimitClass::ShortPositive: return 32767;
    case LimitClass::Switch: return 1;
    case LimitClass::Range: return v.maximum;
    case LimitClass::None: return INT32_MAX;
    }
    return INT32_MAX;
}

bool withinLimits(const VariableInfo& v, std::int64_t basic) {
    if (basic < minimumOf(v) || basic > maximumOf(v)) return false;
    if (v.validValues.empty()) return true;
    return std::any_of(v.validValues.begin(), v.validValues.end(),
                       [basic](const ValueRange& r) { return basic >= r.low && basic <= r.high; });
}

} // namespace drive_core::catalog::bds5
