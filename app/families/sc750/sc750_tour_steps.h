// The screenshot tour's steps for the SC750's Motion Dialogue (issue 8): a ServoBASIC program running on
// the simulated SC750, stopped at a breakpoint with the Output window and Variables filled; a compile
// error marked in the editor; the Real Time Function Call dialog. Last in the tour; the final step
// connects the BDS5 again.
#pragma once

#include "screenshot_tour.h"

#include <vector>

namespace app {

class MainWindow;

std::vector<ScreenshotTour::Step> sc750TourSteps(MainWindow& window);

} // namespace app
