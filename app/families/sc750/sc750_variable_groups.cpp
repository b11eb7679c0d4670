// The SC750 variable browser's groups and value checks.
#include "sc750_variable_groups.h"

#include <QObject>

#include <cmath>

namespace app {

namespace catalog = drive_core::catalog::sc750;

namespace {
QString name(const catalog::VariableInfo& v) {
    return QString::fromLatin1(v.name.data(), qsizetype(v.name.size()));
}

QString number(double value) {
    return QString::number(value, 'g', 10);
}
} // namespace

QStringList sc750VariableGroups() {
    return {QObject::tr("Set-up parameters"),
            QObject::tr("Motion profile"),
            QObject::tr("Position, velocity, current"),
            QObject::tr("Status"),
            QObject::tr("Gearing and encoder"),
            QObject::tr("Registration"),
            QObject::tr("WHEN latches"),
            QObject::tr("I/O"),
            QObject::tr("Interrupt enables"),
            QObject::tr("Timers"),
            QObject::tr("Other")};
}

QString sc750VariableGroup(const catalog::VariableInfo& v) {
    const QStringList groups = sc750VariableGroups();
    const QString n = name(v);
    static const QStringList kProfile{"ACCEL.RATE",   "DECEL.RATE",       "ACCEL.TYPE",        "RUN.SPEED",
                                      "DIR",          "INDEX.DIST",       "TARGET.POS",        "PAUSE.TIME",
                                      "IN.POS.LIMIT", "POS.ERROR.MOVING", "POS.ERROR.STOPPED", "CW.OT.LIMIT",
                                      "CCW.OT.LIMIT"};
    static const QStringList kMotion{"POS.COMMAND", "POSITION",    "POS.ERROR", "RESPOS",  "VELOCITY", "RVEL",
                                     "MOVING",      "IN.POSITION", "VEL.CMD",   "VEL.ERR", "ICMD",     "IFB"};
    static const QStringList kStatus{"ENABLE", "ENABLED",   "FAULTCODE", "TIME",     "MODEL",
                                     "FWV",    "AXIS.ADDR", "LOGGEDON",  "AXIS.INTR"};
    static const QStringList kGearing{"GEARING",    "RATIO",    "PULSES.IN", "PULSES.OUT", "ACCEL.GEAR",
                                      "DECEL.GEAR", "GEARLOCK", "GEARERROR", "ENCPOS",     "COUNTER"};
    static const QStringList kIo{"INPUTS", "OUTPUTS", "PWM12", "ANALOG.OUT", "ANALOG.IN", "DACMON"};
    if (v.access == catalog::Access::Parameter) return groups[0];
    if (kProfile.contains(n)) return groups[1];
    if (kMotion.contains(n)) return groups[2];
    if (kStatus.contains(n)) return groups[3];
    if (kGearing.contains(n) || n.startsWith(QLatin1String("ENC."))) return groups[4];
    if (n.startsWith(QLatin1String("REG."))) return groups[5];
    if (n.startsWith(QLatin1String("WHEN."))) return groups[6];
    if (kIo.contains(n) || n.startsWith(QLatin1String("INP")) || n.startsWith(QLatin1String("OUT"))) return groups[7];
    if (n.startsWith(QLatin1String("INTR."))) return groups[8];
    if (n.startsWith(QLatin1String("TM"))) return groups[9];
    return groups[10];
}

QString sc750RangeText(const catalog::VariableInfo& v) {
    if (v.type == catalog::ValueType::String) return {};
    return QStringLiteral("%1 \u2013 %2").arg(number(v.minimum), number(v.maximum));
}

std::optional<QString> sc750CheckValue(const catalog::VariableInfo& v, const QString& text) {
    const QString n = name(v);
    if (v.access == catalog::Access::ReadOnly) return QObject::tr("%1 is read only.").arg(n);
    const QString t = text.trimmed();
    if (v.type == catalog::ValueType::String) {
        if (t.size() < 2 || !t.startsWith(QLatin1Char('"')) || !t.endsWith(QLatin1Char('"')))
            return QObject::tr("%1 takes a string in double quotes.").arg(n);
        return std::nullopt;
    }
    bool ok = false;
    const double value = t.toDouble(&ok);
    if (!ok) return QObject::tr("%1 takes a number, not \"%2\".").arg(n, t);
    if (v.type == catalog::ValueType::Integer && value != std::floor(value))
        return QObject::tr("%1 is an INTEGER: %2 has a fraction.").arg(n, t);
    if (value < v.minimum || value > v.maximum) return QObject::tr("%1 must lie within %2.").arg(n, sc750RangeText(v));
    return std::nullopt;
}

} // namespace app
