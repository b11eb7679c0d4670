// The screenshot tour's steps for the BDS5 editor: a program with deliberate mistakes showing the drive's
// diagnostics (markers, squiggles, annotations, the status-bar count, the outline), F1 help on a command,
// and the completion list after typing "PE". Appended to ScreenshotTour's list by buildSteps().
#pragma once

#include "screenshot_tour.h"

#include <vector>

namespace app {

class MainWindow;

std::vector<ScreenshotTour::Step> editorTourSteps(MainWindow& window);

} // namespace app
