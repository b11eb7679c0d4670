// BDS5 variable memory.
#include "bds5_variable_store.h"

#include <string>
#include <utility>
#include <vector>

namespace drive_core::bds5 {

namespace cat = catalog::bds5;

namespace {
// A family keeps slots for its extended indices too (X251-X750): they hold 0 while the switch is off.
std::size_t slotCount(const cat::VariableInfo& v) {
    return v.firstIndex == 0 ? 1 : std::size_t(cat::highestIndex(v) - v.firstIndex + 1);
}

// Where each catalog variable lives in the value memory, and what the memory holds when the drive is
// built: the same for every drive, so worked out once (the input fuzzer builds a drive for every input).
struct Layout {
    std::vector<std::size_t> firstSlot;   // per catalog entry
    std::vector<std::ptrdiff_t> slotBase; // per catalog entry: firstSlot less firstIndex (0 for plain variables)
    std::vector<std::int32_t> initial;    // the catalog's power-up values, per slot
    const cat::VariableInfo* inWord = nullptr;
    const cat::VariableInfo* outWord = nullptr;
};

const Layout& layout() {
    static const Layout kLayout = [] {
        const auto vars = cat::variables();
        Layout l;
        l.firstSlot.reserve(vars.size());
        for (const cat::VariableInfo& v : vars) {
            l.firstSlot.push_back(l.initial.size());
            l.slotBase.push_back(std::ptrdiff_t(l.initial.size()) - v.firstIndex);
            l.initial.insert(l.initial.end(), slotCount(v), std::int32_t(v.powerUpValue));
        }
        l.inWord = cat::findVariable("IN")->info;
        l.outWord = cat::findVariable("OUT")->info;
        return l;
    }();
    return kLayout;
}
} // namespace

Bds5VariableStore::Bds5VariableStore()
    : m_base(cat::variables().data()), m_inWord(layout().inWord), m_outWord(layout().outWord),
      m_slotBase(layout().slotBase.data()), m_values(layout().initial) {}

Bds5VariableStore::Slot Bds5VariableStore::slotOf(const cat::VariableRef& ref) {
    const Layout& l = layout();
    if (!ref.info || ref.info == l.inWord || ref.info == l.outWord) return {};
    return {std::size_t(l.slotBase[std::size_t(ref.info - cat::variables().data())] + ref.index)};
}

void Bds5VariableStore::powerUp() {
    const auto vars = cat::variables();
    for (std::size_t i = 0; i < vars.size(); ++i) {
        if (vars[i].persistence != cat::Persistence::Volatile) continue;
        for (std::size_t k = 0; k < slotCount(vars[i]); ++k)
            m_values[layout().firstSlot[i] + k] = std::int32_t(vars[i].powerUpValue);
    }
}

bool Bds5VariableStore::exists(const cat::VariableRef& ref) const {
    if (ref.index <= ref.info->lastIndex || ref.info->extendedBy.empty()) return true;
    const auto on = cat::findVariable(ref.info->extendedBy);
    return on && read(*on) != 0;
}

bool Bds5VariableStore::exists(std::string_view upperName) const {
    const auto ref = cat::findVariable(upperName);
    return ref && exists(*ref);
}

namespace {
// The NUM/DEN pair of each unit class (Tables 4.11-4.16), resolved once.
std::optional<std::pair<cat::VariableRef, cat::VariableRef>> unitPair(cat::UnitClass unit) {
    const auto pair = [](const char* num, const char* den) {
        return std::pair{*cat::findVariable(num), *cat::findVariable(den)};
    };
    static const auto position = pair("PNUM", "PDEN");
    static const auto velocity = pair("VNUM", "VDEN");
    static const auto acceleration = pair("ANUM", "ADEN");
    static const auto current = pair("INUM", "IDEN");
    static const auto extPosition = pair("PXNUM", "PXDEN");
    static const auto extVelocity = pair("VXNUM", "VXDEN");
    switch (unit) {
    case cat::UnitClass::Position: return position;
    case cat::UnitClass::Velocity: return velocity;
    case cat::UnitClass::Acceleration: return acceleration;
    case cat::UnitClass::Current: return current;
    case cat::UnitClass::ExtPosition: return extPosition;
    case cat::UnitClass::ExtVelocity: return extVelocity;
    default: return std::nullopt;
    }
}

// value and the NUM/DEN are 32-bit, so the product fits in 64 bits.
std::optional<std::int64_t> scale(std::int64_t value, std::int64_t num, std::int64_t den) {
    if (den == 0) return std::nullopt;
    const std::int64_t product = value * num;
    std::int64_t q = product / den;
    const std::int64_t r = product % den;
    const std::int64_t absR = r < 0 ? -r : r;
    const std::int64_t absDen = den < 0 ? -den : den;
    if (2 * absR >= absDen) q += ((product < 0) != (den < 0)) ? -1 : 1;
    if (q > INT32_MAX || q < INT32_MIN) return std::nullopt;
    return std::int64_t(q);
}
} // namespace

std::optional<std::int64_t> Bds5VariableStore::toBasic(cat::UnitClass unit, std::int64_t user) const {
    const auto pair = unitPair(unit);
    if (!pair) return user;
    return scale(user, m_values[slot(pair->first)], m_values[slot(pair->second)]);
}

std::optional<std::int64_t> Bds5VariableStore::toUser(cat::UnitClass unit, std::int64_t basic) const {
    const auto pair = unitPair(unit);
    if (!pair) return basic;
    return scale(basic, m_values[slot(pair->second)], m_values[slot(pair->first)]);
}

std::optional<std::int32_t> Bds5VariableStore::read(std::string_view upperName) const {
    const auto ref = cat::findVariable(upperName);
    if (!ref || !exists(*ref)) return std::nullopt;
    return readUser(*ref);
}

std::int32_t Bds5VariableStore::readUser(const cat::VariableRef& ref) const {
    const std::int32_t basic = read(ref);
    if (ref.info->unitClass == cat::UnitClass::None) return basic;
    const auto user = toUser(ref.info->unitClass, basic);
    if (!user) return basic < 0 ? INT32_MIN : INT32_MAX;
    return std::int32_t(*user);
}

std::optional<std::int32_t> Bds5VariableStore::word(const cat::VariableRef& ref) const {
    const bool in = ref.info == m_inWord;
    if (!in && ref.info != m_outWord) return std::nullopt;
    const auto bits = cat::findVariable(in ? "I1" : "O1");
    if (!bits) return std::nullopt;
    const int count = bits->info->lastIndex;
    std::int32_t w = 0;
    for (int i = 1; i <= count; ++i)
        if (m_values[slot(cat::VariableRef{bits->info, i})] != 0) w |= std::int32_t(1) << (i - 1);
    return w;
}

void Bds5VariableStore::setBits(std::string_view stem, int count, std::int32_t w) {
    const auto bits = cat::findVariable(std::string(stem) + "1");
    if (!bits) return;
    for (int i = 1; i <= count && i <= bits->info->lastIndex; ++i)
        m_values[slot(cat::VariableRef{bits->info, i})] = (w >> (i - 1)) & 1;
}

int Bds5VariableStore::write(std::string_view upperName, std::int64_t value, bool driveEnabled) {
    const auto ref = cat::findVariable(upperName);
    if (!ref || !exists(*ref)) return 80; // X251-X750 with EXTDX off: unknown, as before v3 (L7370)
    switch (ref->info->write) {
    case cat::WriteCondition::Never: return 81;
    case cat::WriteCondition::Factory: return 111;
    case cat::WriteCondition::Disabled:
        if (driveEnabled) return 51;
        break;
    case cat::WriteCondition::Always:
    case cat::WriteCondition::NoMotion: break;
    }
    const auto basic = toBasic(ref->info->unitClass, value);
    if (!basic) return 96; // SCALING OVERFLOW (L7445)
    // Limits are kept in basic units, as the catalog's values are (chosen: one scale for both). Out of
    // them is ERR 83 BAD OR OUT OF RANGE, a parameter "too large or too small" (L7380-7382).
    if (!cat::withinLimits(*ref->info, *basic)) return 83;
    // Bounds that are another variable, in basic units: ACC and DEC above AMAX "will generate an error"
    // (L2186-2188), the same ERR 83 (Table E.1: 0-AMAX); VDEFAULT up to VMAX, VOSPD up to 1.2 VMAX, ILIM up
    // to IMAX. The bound is its value now: lowering AMAX later leaves ACC and DEC as they are (decision 2).
    if (!ref->info->maximumVariable.empty()) {
        if (const auto bound = cat::findVariable(ref->info->maximumVariable)) {
            if (*basic * 100 > std::int64_t(read(*bound)) * ref->info->maximumPercent) return 83;
        }
    }
    set(*ref, std::int32_t(*basic));
    return 0;
}

void Bds5VariableStore::setWord(const cat::VariableRef& ref, std::int32_t value) {
    if (ref.info == m_outWord) return setBits("O", 8, value);
    setBits("I", 16, value);
}

void Bds5VariableStore::set(std::string_view upperName, std::int32_t value) {
    if (const auto ref = cat::findVariable(upperName)) set(*ref, value);
}

} // namespace drive_core::bds5
