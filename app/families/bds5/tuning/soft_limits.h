// SoftLimits: the BDS5's software travel limits as P prints them — PLIM, PMAX, PMIN — and PFB, the position
// they are judged from. With PLIM on, motion past PMAX or PMIN stops with ERR 23 (L2237-2259); the power-up
// limits are +-100 counts, which every test move passes, so the tuning panel checks a run's move against them
// before it starts. Pure value type.
#pragma once

#include "test_move.h"

#include <QString>
#include <QStringList>

#include <optional>

namespace app {

struct SoftLimits {
    bool on = true;           // PLIM
    double pmax_units = 100;  // PMAX, position units
    double pmin_units = -100; // PMIN
    double pfb_units = 0;     // PFB, where the move starts

    static QString printLine(); // "P PLIM PMAX PMIN PFB"
    // From the lines P answered printLine() with; nullopt when a value is missing or not a number.
    static std::optional<SoftLimits> parse(const QStringList& lines);
    // Why the drive would stop the move at a limit, for the user: the move, how far it goes, the limit it
    // passes; "" when it stays inside them or PLIM is off.
    QString conflict(const TestMove& move, const TestMove::DriveValues& drive) const;
};

} // namespace app
