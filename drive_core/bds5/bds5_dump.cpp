// BDS5 system dumps.
#include "bds5_dump.h"

#include "drive_core/catalog/bds5_catalog.h"

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
    const int last = v.firstIndex == 0 ? 0 : v.lastIndex;
    for (int i = first; i <= last; ++i) {
        const std::string name = std::string(v.name) + (i ? std::to_string(i) : std::string());
        const auto value = state.variables.read(name);
        if (!value) continue;
        out += (refusedOnUpload(v) ? ";" : "") + name + " " + std::to_string(*value) + "\r\n";
    }
}

} // namespace

std::string dumpAll(const Bds5State& state) {
    std::string out;
    for (const std::string& line : state.program.lines()) out += ";" + line + "\r\n";
    for (const cat::VariableInfo& v : cat::variables())
        if (!isConstant(v)) dumpVariable(state, v, out);
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
