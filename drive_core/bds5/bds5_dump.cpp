// BDS5 system dumps.
#include "bds5_dump.h"

#include "drive_core/catalog/bds5_catalog.h"

#include <string_view>
#include <unordered_set>

namespace drive_core::bds5 {

namespace cat = catalog::bds5;

namespace {

bool refusedOnUpload(const cat::VariableInfo& v) {
    return v.write == cat::WriteCondition::Never || v.write == cat::WriteCondition::Factory;
}

bool isConstant(const cat::VariableInfo& v) {
    return v.name == "ON" || v.name == "OFF" || v.name == "Y" || v.name == "N" || v.name == "CHECKSUM";
}

void dumpVariable(const Bds5State& state, const cat::VariableInfo& v, std::string& out) {
    const int first = v.firstIndex == 0 ? 0 : v.firstIndex;
    const int last = v.firstIndex == 0 ? 0 : cat::highestIndex(v);
    for (int i = first; i <= last; ++i) {
        const std::string name = std::string(v.name) + (i ? std::to_string(i) : std::string());
        const auto value = state.variables.read(name);
        if (!value) continue; // X251-X750 while EXTDX is off
        if (refusedOnUpload(v)) out += ';';
        out += name;
        out += ' ';
        out += std::to_string(*value);
        out += "\r\n";
    }
}

// A variable whose value bounds another's writes (AMAX for ACC and DEC, Table E.1), or decides which of
// another's indices exist (EXTDX for X251-X750, v3 L9309). Collected once: asked of every variable in
// every pass, a search of the catalog each time made DUMP quadratic in its size.
bool boundsOthers(const cat::VariableInfo& v) {
    static const std::unordered_set<std::string_view> kBounds = [] {
        std::unordered_set<std::string_view> names;
        for (const cat::VariableInfo& other : cat::variables()) {
            if (!other.maximumVariable.empty()) names.insert(other.maximumVariable);
            if (!other.extendedBy.empty()) names.insert(other.extendedBy);
        }
        return names;
    }();
    return kBounds.contains(v.name);
}

} // namespace

// Re-sent, the dump must restore every line (decision 8): the bounds come first, so ACC is not refused
// against an AMAX not yet restored, nor X251-X750 against an EXTDX not yet on (decision 15); ADDR comes
// last, so a new ID puts the drive to sleep (and deaf) only after everything else has arrived.
std::string dumpAll(const Bds5State& state) {
    std::string out;
    for (const std::string& line : state.program.lines()) out += ";" + line + "\r\n";
    enum class Pass { Bounds, Rest, Address };
    const auto passOf = [](const cat::VariableInfo& v) {
        return v.name == "ADDR" ? Pass::Address : boundsOthers(v) ? Pass::Bounds : Pass::Rest;
    };
    for (const Pass pass : {Pass::Bounds, Pass::Rest, Pass::Address})
        for (const cat::VariableInfo& v : cat::variables())
            if (!isConstant(v) && passOf(v) == pass) dumpVariable(state, v, out);
    return out;
}

std::string dumpLoopGains(const Bds5State& state) {
    std::string out;
    for (const cat::VariableInfo& v : cat::variables())
        if (v.group == cat::VariableGroup::LoopGains || v.name == "LPF" || v.name == "LPFHZ")
            dumpVariable(state, v, out);
    return out;
}

std::string dumpVersion() {
    return std::string(kFirmwareVersion) + "\r\n";
}

} // namespace drive_core::bds5
