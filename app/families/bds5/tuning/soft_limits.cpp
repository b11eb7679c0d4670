// SoftLimits: reading PLIM/PMAX/PMIN/PFB and judging a test move against them.
#include "soft_limits.h"

#include <QObject>

#include <cmath>

namespace app {

QString SoftLimits::printLine() {
    return QStringLiteral("P PLIM PMAX PMIN PFB");
}

std::optional<SoftLimits> SoftLimits::parse(const QStringList& lines) {
    // P prints a switch as 1 or 0; ON and OFF are taken too.
    const auto number = [](const QString& word) -> std::optional<double> {
        if (word.compare(QLatin1String("ON"), Qt::CaseInsensitive) == 0) return 1.0;
        if (word.compare(QLatin1String("OFF"), Qt::CaseInsensitive) == 0) return 0.0;
        bool ok = false;
        const double v = word.toDouble(&ok);
        return ok ? std::optional<double>(v) : std::nullopt;
    };
    const QStringList words = lines.join(QLatin1Char(' ')).split(QLatin1Char(' '), Qt::SkipEmptyParts);
    if (words.size() != 4) return std::nullopt;
    const auto plim = number(words[0]), pmax = number(words[1]), pmin = number(words[2]), pfb = number(words[3]);
    if (!plim || !pmax || !pmin || !pfb) return std::nullopt;
    return SoftLimits{*plim != 0, *pmax, *pmin, *pfb};
}

QString SoftLimits::conflict(const TestMove& move, const TestMove::DriveValues& drive) const {
    if (!on) return {};
    const TestMove::Travel travel = move.travel(drive);
    const auto n = [](double v) { return QString::number(std::llround(v)); };
    if (pfb_units + travel.highest_units > pmax_units)
        return QObject::tr("The test move (%1) takes the motor about %2 position units forward from PFB %3, past "
                           "the software limit PMAX %4: with PLIM on, the drive would stop it with ERR 23 "
                           "SOFTWARE OVERTRAVEL.")
            .arg(move.description(), n(travel.highest_units), n(pfb_units), n(pmax_units));
    if (pfb_units + travel.lowest_units < pmin_units)
        return QObject::tr("The test move (%1) takes the motor about %2 position units back from PFB %3, past "
                           "the software limit PMIN %4: with PLIM on, the drive would stop it with ERR 23 "
                           "SOFTWARE OVERTRAVEL.")
            .arg(move.description(), n(-travel.lowest_units), n(pfb_units), n(pmin_units));
    return {};
}

} // namespace app
