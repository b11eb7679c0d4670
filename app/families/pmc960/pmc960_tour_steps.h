// The screenshot tour's PMC-960 steps (issue 9): an MPL program in the editor with its colours and F1
// help, the status panel after a move, the parameter table with stored vs in-use values. Switches the
// family to the PMC-960 and back to the BDS5 at the end; appended last by ScreenshotTour::buildSteps().
#pragma once

#include "screenshot_tour.h"

#include <vector>

namespace app {

class MainWindow;

std::vector<ScreenshotTour::Step> pmc960TourSteps(MainWindow& window);

} // namespace app
