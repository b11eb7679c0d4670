// BDS5 system dumps.
#include "bds5_dump.h"

#include "drive_core/catalog/bds5_catalog.h"

#include <vector>

namespace drive_core::bds5 {

namespace cat = catalog::bds5;

namespace {

bool refusedOnUpload(const cat::VariableInfo& v) {
    return v.write == cat::WriteCondition::Never || v.write == cat::WriteCondition::Factory;
}

bool isConstant(const cat::VariableInfo& v) {
    return v.name == "ON" || v.name == "OFF" || v.name == "Y" || v.name == "N" || v.name == "CHECKSUM";
}

// The value is read through the catalog entry itself: every name the dump prints resolves to that entry
// and index (the catalog's names are unique), and looking up ~1,100 names made DUMP the costliest thing
// the input fuzzer typed (issue 20).
void dumpVariable(const Bds5State& state, const cat::VariableInfo& v, std::string& out) {
    const int first = v.firstIndex == 0 ? 0 : v.firstIndex;
    const int last = v.firstIndex == 0 ? 0 : cat::highestIndex(v);
    for (int i = first; i <= last; ++i) {
        const cat::VariableRef ref{&v, i};
        if (i > v.lastIndex && !state.variables.exists(ref)) break; // X251-X750 while EXTDX is off
        if (refusedOnUpload(v)) out += ';';
        out += v.name;
        if (i) out += std::to_string(i);
        out += ' ';
        out += std::to_string(state.variables.readUser(ref));
        out += "\r\n";
    }
}

// A variable whose value bounds another's writes (AMAX for ACC and DEC, Table E.1), or decides which of
// another's indices exist (EXTDX for X251-X750, v3 L9309).
bool boundsOthers(const cat::VariableInfo& v) {
    for (const cat::VariableInfo& other : cat::variables())
        if (other.maximumVariable == v.name || other.extendedBy == v.name) return true;
    return false;
}

// Re-sent, the dump must restore every line (decision 8): the bounds come first, so ACC is not refused
// against an AMAX not yet restored, nor X251-X750 against an EXTDX not yet on (decision 15); ADDR comes
// last, so a new ID puts the drive to sleep (and deaf) only after everything else has arrived. The order
// is the catalog's, so it is worked out once (for every DUMP it was a search of the catalog for each
// variable in each pass, the costliest thing the input fuzzer typed, issue 20).
const std::vector<const cat::VariableInfo*>& dumpOrder() {
    static const std::vector<const cat::VariableInfo*> kOrder = [] {
        enum class Pass { Bounds, Rest, Address };
        const auto passOf = [](const cat::VariableInfo& v) {
            return v.name == "ADDR" ? Pass::Address : boundsOthers(v) ? Pass::Bounds : Pass::Rest;
        };
        std::vector<const cat::VariableInfo*> order;
        for (const Pass pass : {Pass::Bounds, Pass::Rest, Pass::Address})
            for (const cat::VariableInfo& v : cat::variables())
                if (!isConstant(v) && passOf(v) == pass) order.push_back(&v);
        return order;
    }();
    return kOrder;
}

} // namespace

// The program as comment lines, then the variables in dumpOrder().
std::string dumpAll(const Bds5State& state) {
    std::string out;
    for (const std::string& line : state.program.lines()) out += ";" + line + "\r\n";
    for (const cat::VariableInfo* v : dumpOrder()) dumpVariable(state, *v, out);
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
