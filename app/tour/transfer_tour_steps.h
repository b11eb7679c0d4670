// The screenshot tour's steps for the Program and Variables menus: a download in progress, its result, a
// drive error marked at its editor line after running the program, and a variable set read from the drive.
// Appended to ScreenshotTour's list by buildSteps().
#pragma once

#include "screenshot_tour.h"

#include <vector>

namespace app {

class MainWindow;

std::vector<ScreenshotTour::Step> transferTourSteps(MainWindow& window);

} // namespace app
