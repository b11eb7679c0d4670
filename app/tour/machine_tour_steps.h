// Machine tour steps (issue 21): the Axes panel after a scan of a simulated 4-axis BDS5 line, and Compare
// after a backup and one changed variable.
#pragma once

#include "screenshot_tour.h"

#include <vector>

namespace app {

class MainWindow;

std::vector<ScreenshotTour::Step> machineTourSteps(MainWindow& window);

} // namespace app
