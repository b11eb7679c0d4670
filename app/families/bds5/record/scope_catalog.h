// What the scope and tuning panel read from the BDS5 catalog: the variables RECORD accepts, each variable's
// unit name, and the limits of the tuning gains in the units the drive prints them.
#pragma once

#include <QString>
#include <QStringList>

#include <string>

namespace app {

struct GainInfo {
    QString name;        // "KV"
    QString description; // the manual's words
    QString unit;        // "" for plain gains, "Hz", "%"
    int minimum = 0;     // in the units P prints
    int maximum = 0;
    int powerUp = 0;
    bool isSwitch = false;
};

// Every plain variable the drive can RECORD, in catalog order (VFB, VCMD, ICMD, PFB, ...).
QStringList recordableVariables();
// Every plain variable and switch P can print (for the polled chart), the recordable tuning signals first.
QStringList pollableVariables();
// The manual's unit name of a variable ("VEL", "POS", "I", "Hz"), "" when it has none or is unknown.
std::string unitOf(const std::string& variable);
// The tuning panel's gains (KP, KF, KV, KVI, KPROP, LPFHZ, ILIM) and switches (LPF, PL, PROP, PLIM).
QList<GainInfo> tuningGains();
GainInfo gainInfo(const QString& name);

// RECORD <n> limit for this many variables (1000, 500, 333, 250), L6378-6381.
int recordSampleLimit(int variableCount);

} // namespace app
