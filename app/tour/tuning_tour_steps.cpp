// The family tuning shots: sc750-tuning (KVFF at 100, then KVP doubled) and pmc960-tuning (TGF100, VLGAIN 4
// then 16), as the manual's tuning procedure raises a gain between test moves, and sc750-bode, the velocity
// loop's frequency response of the SC750's last run. Each ends on the BDS5 again.
#include "tuning_tour_steps.h"

#include "family_workspace.h"
#include "main_window.h"
#include "scope/bode_view.h"
#include "app/tuning/family_tuning_runner.h"
#include "app/tuning/tuning_panel.h"

#include <QAction>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QMenu>
#include <QPointer>
#include <QTableWidget>

#include <memory>

namespace app {

namespace {
TuningPanel* panelOf(MainWindow& window, drive_core::DriveFamily family) {
    FamilyWorkspace* ws = window.workspace(family);
    if (!ws) return nullptr;
    for (QDockWidget* dock : ws->docks())
        if (auto* panel = qobject_cast<TuningPanel*>(dock->widget())) return panel;
    return nullptr;
}

QDockWidget* dockOf(TuningPanel* panel) {
    return panel ? qobject_cast<QDockWidget*>(panel->parentWidget()) : nullptr;
}

// One shot: connect, open the panel from the family's menu, set `first` gains, run, raise `gain` to `raised`,
// run again; grab the floating dock once both runs are in.
ScreenshotTour::Step tuningStep(MainWindow& window, drive_core::DriveFamily family, const QString& name,
                                QList<QPair<QString, double>> first, QString gain, double raised) {
    auto stage = std::make_shared<int>(0);
    return {.name = name,
            .act =
                [&window, family, stage] {
                    *stage = 0;
                    window.connectDrive(ConnectionChoice::simulator(family));
                    for (QMenu* menu : window.workspace(family)->menus())
                        for (QAction* a : menu->actions())
                            if (a->text() == QStringLiteral("Tuning &Panel")) a->trigger();
                    TuningPanel* panel = panelOf(window, family);
                    QDockWidget* dock = dockOf(panel);
                    dock->setFloating(true);
                    dock->resize(1240, 600);
                    panel->hold()->setValue(150);
                },
            // As a user would: wait for the gains read from the drive, set the first ones, run once when the drive
            // has confirmed them, raise the gain, run again (the run queues behind the gain's write).
            .ready =
                [&window, family, first, gain, raised, stage] {
                    TuningPanel* panel = panelOf(window, family);
                    if (!panel || !window.workspace(family)->isConnected()) return false;
                    FamilyTuningRunner& runner = panel->runner<app::FamilyTuningRunner>();
                    const QString confirmed = QStringLiteral("\u2713");
                    switch (*stage) {
                    case 0:
                        if (panel->gainMark(gain) != confirmed) return false; // not read yet
                        for (const auto& [g, value] : first) panel->gainEditor(g)->setValue(value);
                        *stage = 1;
                        return false;
                    case 1:
                        for (const auto& [g, value] : first)
                            if (panel->gainMark(g) != confirmed) return false;
                        runner.runOnce();
                        *stage = 2;
                        return false;
                    case 2:
                        if (runner.isRunning() || runner.runs().isEmpty()) return false;
                        panel->gainEditor(gain)->setValue(raised);
                        runner.runOnce();
                        *stage = 3;
                        return false;
                    default: return !runner.isRunning() && runner.runs().size() >= 2;
                    }
                },
            .grab = [&window, family] { return TourShot::of(dockOf(panelOf(window, family))); },
            .cleanUp =
                [&window, family] {
                    if (QDockWidget* dock = dockOf(panelOf(window, family))) {
                        dock->setFloating(false);
                        dock->hide();
                    }
                    window.connectDrive(ConnectionChoice::simulator(drive_core::DriveFamily::Bds5));
                },
            .state = [&window, family] {
                TuningPanel* panel = panelOf(window, family);
                return panel ? QStringLiteral("%1 run(s); %2").arg(panel->runner<app::FamilyTuningRunner>().runs().size()).arg(panel->statusText())
                             : QStringLiteral("no tuning panel");
            }};
}
} // namespace

// The Frequency Response of the panel's newest run (the runs stay with the panel after it disconnects).
ScreenshotTour::Step bodeStep(MainWindow& window, drive_core::DriveFamily family, const QString& name) {
    return {.name = name,
            .act =
                [&window, family] {
                    TuningPanel* panel = panelOf(window, family);
                    panel->runsTable()->clearSelection();
                    panel->runsTable()->setCurrentItem(nullptr);
                    panel->frequencyResponse()->resize(760, 600);
                },
            .ready =
                [&window, family] {
                    BodeView* bode = panelOf(window, family)->frequencyResponse();
                    return bode->isVisible() && bode->response().bandwidth_hz.has_value();
                },
            .grab = [&window, family] { return TourShot::of(panelOf(window, family)->frequencyResponse()); },
            .cleanUp = [&window, family] { panelOf(window, family)->frequencyResponse()->close(); },
            .state = [&window, family] { return panelOf(window, family)->frequencyResponse()->summary(); }};
}

std::vector<ScreenshotTour::Step> tuningTourSteps(MainWindow& window) {
    std::vector<ScreenshotTour::Step> steps;
    if (!panelOf(window, drive_core::DriveFamily::Sc750) || !panelOf(window, drive_core::DriveFamily::Pmc960)) return steps;
    TuningPanel* sc750 = panelOf(window, drive_core::DriveFamily::Sc750);
    const double kvp = sc750->gainEditor(QStringLiteral("KVP"))->value(); // the catalog's power-up value until read
    steps.push_back(tuningStep(window, drive_core::DriveFamily::Sc750, QStringLiteral("sc750-tuning"),
                               {{QStringLiteral("KVFF"), 100}}, QStringLiteral("KVP"), 2 * std::max(kvp, 0.087)));
    steps.push_back(bodeStep(window, drive_core::DriveFamily::Sc750, QStringLiteral("sc750-bode")));
    steps.push_back(tuningStep(window, drive_core::DriveFamily::Pmc960, QStringLiteral("pmc960-tuning"),
                               {{QStringLiteral("FFGAIN"), 100}, {QStringLiteral("VLGAIN"), 4}},
                               QStringLiteral("VLGAIN"), 16));
    return steps;
}

} // namespace app
