// Scope and tuning facts from the catalog.
#include "scope_catalog.h"

#include "drive_core/catalog/bds5_catalog.h"

#include <QHash>

namespace app {

namespace cat = drive_core::catalog::bds5;

namespace {
constexpr int kRecordPoints = 1000;
constexpr double kFullCurrentBasic = 4095; // current's basic units at 100 % (user units print %)
// PLIM too: with the factory PMAX/PMIN of +-100 counts a test move stops at once with ERR 23.
const char* const kGains[] = {"KP", "KF", "KV", "KVI", "KPROP", "LPFHZ", "ILIM", "LPF", "PL", "PROP", "PLIM"};

int toUser(const cat::VariableInfo& v, std::int64_t basic) {
    if (v.unitClass == cat::UnitClass::Current) return int(std::llround(double(basic) * 100 / kFullCurrentBasic));
    return int(std::clamp<std::int64_t>(basic, INT32_MIN, INT32_MAX));
}
} // namespace

QStringList recordableVariables() {
    QStringList names;
    for (const cat::VariableInfo& v : cat::variables()) {
        if (!v.recordable || v.firstIndex != 0 || v.isSwitch) continue;
        names << QString::fromLatin1(v.name.data(), qsizetype(v.name.size()));
    }
    // The usual tuning signals first, in the order people pick them.
    const QStringList first = {QStringLiteral("VCMD"), QStringLiteral("VFB"), QStringLiteral("ICMD"),
                               QStringLiteral("PCMD"), QStringLiteral("PFB")};
    QStringList ordered;
    for (const QString& n : first)
        if (names.contains(n)) ordered << n;
    for (const QString& n : names)
        if (!ordered.contains(n)) ordered << n;
    return ordered;
}

QStringList pollableVariables() {
    QStringList names = recordableVariables();
    for (const cat::VariableInfo& v : cat::variables()) {
        const QString name = QString::fromLatin1(v.name.data(), qsizetype(v.name.size()));
        if (v.firstIndex == 0 && !names.contains(name)) names << name;
    }
    return names;
}

std::string unitOf(const std::string& variable) {
    const auto ref = cat::findVariable(variable);
    if (!ref) return {};
    if (ref->info->unitClass == cat::UnitClass::Current) return "%";
    return std::string(ref->info->units);
}

GainInfo gainInfo(const QString& name) {
    GainInfo g;
    g.name = name;
    const auto ref = cat::findVariable(name.toStdString());
    if (!ref) return g;
    const cat::VariableInfo& v = *ref->info;
    g.description = QString::fromLatin1(v.description.data(), qsizetype(v.description.size()));
    g.unit = QString::fromStdString(unitOf(name.toStdString()));
    g.isSwitch = v.isSwitch || v.limits == cat::LimitClass::Switch;
    g.minimum = std::max(toUser(v, cat::minimumOf(v)), v.unitClass == cat::UnitClass::Current ? 1 : INT32_MIN);
    g.maximum = toUser(v, cat::maximumOf(v));
    g.powerUp = toUser(v, v.powerUpValue);
    return g;
}

QList<GainInfo> tuningGains() {
    QList<GainInfo> gains;
    for (const char* name : kGains) gains << gainInfo(QString::fromLatin1(name));
    return gains;
}

int recordSampleLimit(int variableCount) {
    return variableCount > 0 ? kRecordPoints / variableCount : kRecordPoints;
}

} // namespace app
