// Axis status: the queries and their words.
#include "axis_status.h"

namespace app::machine {

using drive_core::DriveFamily;

QStringList statusQueries(DriveFamily family) {
    switch (family) {
    case DriveFamily::Bds5: return {QStringLiteral("P READY"), QStringLiteral("P FAULT"), QStringLiteral("P CHECKSUM")};
    case DriveFamily::Sc750:
        return {QStringLiteral("MODEL"), QStringLiteral("FWV"), QStringLiteral("ENABLED"), QStringLiteral("FAULTCODE")};
    case DriveFamily::Pmc960: return {QStringLiteral("SS!")};
    }
    return {};
}

QString statusText(DriveFamily family, const QStringList& answers) {
    const auto at = [&answers](int i) { return answers.value(i).trimmed(); };
    const auto enabled = [](bool on) { return on ? QStringLiteral("enabled") : QStringLiteral("disabled"); };
    switch (family) {
    case DriveFamily::Bds5:
        return QStringLiteral("%1, %2, program checksum %3")
            .arg(enabled(at(0) == QLatin1String("1")),
                 at(1) == QLatin1String("0") ? QStringLiteral("no fault") : QStringLiteral("FAULT"), at(2));
    case DriveFamily::Sc750:
        return QStringLiteral("SC%1 firmware %2, %3, %4")
            .arg(at(0), at(1), enabled(at(2) == QLatin1String("1")),
                 at(3) == QLatin1String("0") ? QStringLiteral("no fault") : QStringLiteral("fault code %1").arg(at(3)));
    case DriveFamily::Pmc960: {
        bool hex = false;
        const int bits = at(0).toInt(&hex, 16);
        if (!hex) return QStringLiteral("snapshot \"%1\"").arg(at(0));
        return QStringLiteral("%1%2").arg(enabled(bits & 0x80), bits & 0x08 ? QStringLiteral(", in motion") : QString());
    }
    }
    return {};
}

} // namespace app::machine
