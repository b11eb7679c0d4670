// makeFamilyTuningDock: the dock, its panel and its action.
#include "family_tuning_dock.h"

#include "family_tuning_runner.h"
#include "tuning_panel.h"

#include "main_window.h"

#include "drive_core/drive_factory.h"
#include "terminal_dock.h"
#include "terminal_tabs.h"

#include <QAction>
#include <QDockWidget>

namespace app {

FamilyTuningDock makeFamilyTuningDock(MainWindow& window, drive_core::DriveFamily family) {
    FamilyTuningDock t;
    const auto profile = tuningProfile(family);
    if (!profile) return t;
    const QString name = QString::fromLatin1(drive_core::familyName(family));
    t.dock = new QDockWidget(QObject::tr("Tuning"), &window);
    t.dock->setObjectName(name + QStringLiteral("TuningDock"));
    t.panel = new TuningPanel(new FamilyTuningRunner(*profile), t.dock);
    t.panel->setStatus(QObject::tr("Not connected."));
    t.dock->setWidget(t.panel);
    t.action = terminalTabAction(window, window.terminalDock(), t.dock, QObject::tr("Tuning &Panel"), t.dock);
    t.action->setStatusTip(QObject::tr("Gains, a test move and the response on the bench's oscilloscope, run after run"));
    return t;
}

void attachTuning(TuningPanel& panel, serialport::DriveSession* session, serialport::Link* link) {
    auto& runner = panel.runner<FamilyTuningRunner>();
    runner.attach(session, link);
    panel.setStatus(session ? QObject::tr("Connected: reading the gains\u2026") : QObject::tr("Not connected."));
    if (session) runner.readGains();
}

} // namespace app
