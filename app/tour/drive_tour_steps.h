// The screenshot tour's steps for drive control: single-stepping the manual's 55$ with the line about to
// run highlighted, a traced program running in the terminal, the capture of that session, the Options
// dialog and the BDS5 reference. Appended to ScreenshotTour's list by buildSteps().
#pragma once

#include "screenshot_tour.h"

#include <vector>

namespace app {

class MainWindow;

std::vector<ScreenshotTour::Step> driveTourSteps(MainWindow& window);

} // namespace app
