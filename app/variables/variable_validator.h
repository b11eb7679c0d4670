// VariableValidator: checks an edit of a BDS5 variable before it is sent, the way the drive would — the
// catalog's limits and programming condition — and names the error the drive would give (ERR 83, 51...).
// Pure; no I/O. Values are in the user units the drive prints; limits are converted with NUM/DEN when known.
#pragma once

#include "variable_rules.h"

#include "drive_core/catalog/bds5_catalog.h"

#include <QCoreApplication>
#include <QString>

#include <functional>
#include <optional>

namespace app {

class VariableValidator {
    Q_DECLARE_TR_FUNCTIONS(VariableValidator)

public:
    // What the validator knows about the drive; a lookup returns nullopt when the value is not known yet.
    using Context = VariableRules::Context;
    struct Verdict {
        bool ok = false;
        QString instruction; // "NAME value", ready to send, when ok
        QString message;     // why not, naming the drive's error ("ERR 83 BAD OR OUT OF RANGE: ...")
    };

    // name is upper-case ("VMAX", "X12"); text as the user typed it ("3000", "ON", "-1.5").
    static Verdict check(const QString& name, const QString& text, const Context& context);

    // The user-unit limits of a variable, if they can be stated: class limits scaled by NUM/DEN.
    static std::optional<std::pair<double, double>> userLimits(const drive_core::catalog::bds5::VariableInfo& info,
                                                               const Context& context);
    // The (numerator, denominator) variable names for a unit class; empty when none scales it.
    static std::pair<QString, QString> unitPair(drive_core::catalog::bds5::UnitClass unitClass);
    // "ERR 83 BAD OR OUT OF RANGE" from the catalog.
    static QString driveError(int code);
};

} // namespace app
