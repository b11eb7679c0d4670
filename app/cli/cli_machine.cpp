// servodesk-cli machine scan: the axes of a BDS5 multidrop line (issue 21).
#include "cli_runner.h"

#include "serialport/bds5_bus_scan.h"
#include "serialport/link.h"
#include "serialport/port_link.h"

#include <QElapsedTimer>

namespace app::cli {

// Alone on its connection: a line of sleeping axes never makes a session ready, and the scan leaves every axis
// asleep again.
void CliRunner::machineScan(const CliCommand& c) {
    if (m_options.commands.size() != 1)
        return fail(kUsage, QStringLiteral("machine scan runs alone: give it its own servodesk-cli call"));
    if (m_options.simulated)
        return fail(kUsage, QStringLiteral("machine scan needs --port: a multidrop line (servodesk-sim --axes serves "
                                           "one)"));
    if (m_family != drive_core::DriveFamily::Bds5)
        return fail(kUsage, QStringLiteral("machine scan is for a BDS5 line; the %1's addressing is not supported yet")
                                .arg(familyDisplayName(m_family)));
    const QString ids = c.scanIds.isEmpty() ? serialport::Bds5BusScan::allIds() : c.scanIds;
    for (const QChar id : ids)
        if (!serialport::Bds5BusScan::allIds().contains(id))
            return fail(kUsage, QStringLiteral("machine scan --ids: %1 is not an axis ID (0-9, A-Z)").arg(id));
    m_link = serialport::makePortLink(m_options.port, m_options.baud, m_family);
    auto* scan = new serialport::Bds5BusScan(*m_link, ids, c.scanWaitMs, this);
    auto* clock = new QElapsedTimer;
    connect(m_link.get(), &serialport::Link::errorOccurred, this, [this](const QString& why) { fail(kNoAnswer, why); });
    connect(m_link.get(), &serialport::Link::opened, this, [scan, clock] {
        clock->start();
        scan->start();
    });
    connect(scan, &serialport::Bds5BusScan::progress, this, [this, ids](int called, int total) {
        progress(QStringLiteral("calling axis %1 (%2 of %3)").arg(ids.at(called)).arg(called + 1).arg(total));
    });
    connect(scan, &serialport::Bds5BusScan::finished, this,
            [this, clock, ids](const QList<serialport::Bds5BusScan::Axis>& axes) {
                for (const auto& a : axes)
                    out(QStringLiteral("%1 BDS5 %2 %3\n").arg(a.id).arg(a.mode, a.prompt));
                std::fprintf(stderr, "machine scan: %lld axes answered of %lld IDs called, in %.2f s on %s\n",
                             qlonglong(axes.size()), qlonglong(ids.size()), clock->elapsed() / 1000.0,
                             qPrintable(m_link->description()));
                delete clock;
                if (axes.isEmpty()) return fail(kNoAnswer, QStringLiteral("no axis answered on %1").arg(m_link->description()));
                emit done(kOk);
            });
    m_link->open();
}

} // namespace app::cli
