// The screenshot tour's steps for issue 7's docks and dialogs: the variable browser with live values, the
// error log with several severities, three setup-wizard pages, the DEP-01 panel and the simulator's I/O
// panel. Appended to ScreenshotTour's list by buildSteps().
#pragma once

#include "screenshot_tour.h"

#include <vector>

namespace app {

class MainWindow;

std::vector<ScreenshotTour::Step> docksTourSteps(MainWindow& window);

} // namespace app
