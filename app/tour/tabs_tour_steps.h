// The screenshot tour's steps for tabs and Motion Link's editor functions: three files of the three
// Motion Link types in tabs (with the classic keymap waiting for the second key of ^K), the find and
// replace bar, go to line without counting comment lines, and the size of the editor. Appended to
// ScreenshotTour's list by buildSteps(); the example files are written under the tour's folder.
#pragma once

#include "screenshot_tour.h"

#include <vector>

namespace app {

class MainWindow;

std::vector<ScreenshotTour::Step> tabsTourSteps(MainWindow& window, const QDir& outputDir);

} // namespace app
