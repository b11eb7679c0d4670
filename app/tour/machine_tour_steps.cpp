// Machine tour steps: scan, back up, change one axis, compare.
#include "machine_tour_steps.h"

#include "main_window.h"

#include "machine/axes_dock.h"
#include "machine/axis_errand.h"

#include <QListWidget>
#include <QTableWidget>
#include <QTemporaryDir>

#include <memory>

namespace app {

std::vector<ScreenshotTour::Step> machineTourSteps(MainWindow& window) {
    AxesDock* dock = window.axesDock();
    auto backup = std::make_shared<QTemporaryDir>();
    auto changed = std::make_shared<bool>(false);
    std::vector<ScreenshotTour::Step> steps;
    steps.push_back({.name = QStringLiteral("axes-panel"),
                     .act =
                         [dock] {
                             dock->setFloating(true);
                             dock->show();
                             dock->resize(640, 360);
                             dock->raise();
                             dock->setSimulatorSpeed(20); // the scan's seconds of drive time in a moment
                             dock->setSimulatedLine(drive_core::DriveFamily::Bds5, QStringLiteral("A,B,C,D"));
                             dock->scan();
                         },
                     .ready = [dock] { return !dock->isBusy() && dock->table()->rowCount() == 4; },
                     .grab = [dock] { return TourShot::of(dock); },
                     .state = [dock] { return dock->statusText(); }});
    steps.push_back({.name = QStringLiteral("machine-backup"),
                     .act = [dock, backup] { dock->backUpTo(backup->filePath(QStringLiteral("line-3"))); },
                     .ready = [dock] { return !dock->isBusy() && dock->statusText().contains(QStringLiteral("backed up")); },
                     .grab = [dock] { return TourShot::of(dock); },
                     .state = [dock] { return dock->statusText(); }});
    steps.push_back({.name = QStringLiteral("machine-change"),
                     .act =
                         [dock, changed] {
                             auto* errand = new machine::AxisErrand(*dock->line(), drive_core::DriveFamily::Bds5,
                                                                    QStringLiteral("B"), dock);
                             QObject::connect(errand, &machine::AxisErrand::finished, errand, [errand, changed] {
                                 *changed = true;
                                 errand->deleteLater();
                             });
                             errand->sendLines({QStringLiteral("X1=5"), QStringLiteral("ACC 50000")});
                         },
                     .ready = [changed] { return *changed; }});
    steps.push_back({.name = QStringLiteral("machine-compare"),
                     .act = [dock, backup] { dock->compareWith(backup->filePath(QStringLiteral("line-3"))); },
                     .ready = [dock] { return !dock->isBusy() && dock->compareDialog() && dock->compareDialog()->isVisible(); },
                     .grab = [dock] { return TourShot::of(dock->compareDialog()); },
                     .cleanUp =
                         [dock] {
                             dock->compareDialog()->close();
                             dock->hide();
                             dock->setFloating(false);
                         },
                     .state = [dock] { return dock->statusText(); }});
    return steps;
}

} // namespace app
