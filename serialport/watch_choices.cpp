// Each family's values to watch, from its catalog.
#include "watch_choices.h"

#include "drive_core/catalog/bds5_catalog.h"
#include "drive_core/catalog/sc750_catalog.h"

#include <QCoreApplication>

namespace serialport {

namespace {
QString tr(const char* text) {
    return QCoreApplication::translate("serialport::WatchChoices", text);
}

QString text(std::string_view s) {
    return QString::fromLatin1(s.data(), qsizetype(s.size()));
}

// The BDS5: what P prints — every plain variable and switch (indexed families such as X1 left out), the
// tuning signals RECORD takes first, in the order people pick them. Currents print in % of peak.
QList<WatchChoice> bds5Choices() {
    namespace cat = drive_core::catalog::bds5;
    const auto unit = [](const cat::VariableInfo& v) {
        return v.unitClass == cat::UnitClass::Current ? QStringLiteral("%") : text(v.units);
    };
    QList<WatchChoice> first, recordable, rest;
    const QStringList kFirst{QStringLiteral("VCMD"), QStringLiteral("VFB"), QStringLiteral("ICMD"),
                             QStringLiteral("PCMD"), QStringLiteral("PFB")};
    for (const QString& name : kFirst)
        if (const auto ref = cat::findVariable(name.toStdString())) first.append({name, name, unit(*ref->info)});
    for (const cat::VariableInfo& v : cat::variables()) {
        const QString name = text(v.name);
        if (v.firstIndex != 0 || kFirst.contains(name)) continue;
        (v.recordable && !v.isSwitch ? recordable : rest).append({name, name, unit(v)});
    }
    return first + recordable + rest;
}

// The SC750: every numeric variable a G frame reads, the values that move (read-only state) first.
QList<WatchChoice> sc750Choices() {
    namespace cat = drive_core::catalog::sc750;
    QList<WatchChoice> state, settable;
    for (const cat::VariableInfo& v : cat::variables()) {
        if (v.type == cat::ValueType::String) continue;
        (v.access == cat::Access::ReadOnly ? state : settable).append({text(v.name), text(v.name), text(v.units)});
    }
    return state + settable;
}

// The PMC-960: what its status polls answer (<attn> g f v i, digest §4.7), named after the display commands
// that show the same values. V! counts in the velocity range's units (100 Hz in the 192 kHz range).
QList<WatchChoice> pmc960Choices() {
    return {{QStringLiteral("G"), tr("Position (G!)"), tr("counts")},
            {QStringLiteral("SF"), tr("Following error (SF!)"), tr("counts")},
            {QStringLiteral("V"), tr("Velocity (V!)"), tr("V units")},
            {QStringLiteral("I"), tr("Distance to go (I!)"), tr("counts")}};
}
} // namespace

QList<WatchChoice> watchChoices(drive_core::DriveFamily family) {
    switch (family) {
    case drive_core::DriveFamily::Bds5: return bds5Choices();
    case drive_core::DriveFamily::Sc750: return sc750Choices();
    case drive_core::DriveFamily::Pmc960: return pmc960Choices();
    }
    return {};
}

std::optional<WatchChoice> findWatchChoice(drive_core::DriveFamily family, const QString& name) {
    for (const WatchChoice& c : watchChoices(family))
        if (c.name.compare(name.trimmed(), Qt::CaseInsensitive) == 0) return c;
    return std::nullopt;
}

QStringList watchNames(drive_core::DriveFamily family) {
    QStringList names;
    for (const WatchChoice& c : watchChoices(family)) names << c.name;
    return names;
}

QString watchMethod(drive_core::DriveFamily family) {
    switch (family) {
    case drive_core::DriveFamily::Bds5: return tr("P prints the ticked variables, polled as fast as the link answers.");
    case drive_core::DriveFamily::Sc750:
        return tr("Each is read with a G frame in turn, as fast as the controller answers; a running program "
                  "keeps running.");
    case drive_core::DriveFamily::Pmc960:
        return tr("Each is an out-of-band status poll (<attn> g, f, v, i), answered even while a program runs.");
    }
    return {};
}

} // namespace serialport
