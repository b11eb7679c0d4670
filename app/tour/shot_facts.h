// shotFacts: what a tour shot shows, read from its widgets at the grab and saved beside the PNG as
// "<name>.png.facts", so a test can ask whether a picture is the view it should be without reading pixels.
// GUI thread only.
//
// One fact a line, "kind: text", layer by layer in the widget tree's order, from the widgets the picture shows
// (visible, in the grabbed window, not clipped or cropped away). Texts are trimmed to one line; a text of
// several lines gives one fact a line.
//   window: T       the title of a grabbed window (main window, dialog, floated dock)
//   dock: T         a visible dock's title
//   tab: T          the current tab of a tab bar      tabs: A | B | C   all of its tabs
//   label: T        a label's text (rich text as plain text)
//   button: T       a button's text; "[x] T" or "[ ] T" when it is checkable
//   check: [x] T    a check box or radio button
//   group: T        a group box's title ("[x] T" when checkable)
//   edit: T         a line edit's or spin box's text   combo: T     a combo box's current text
//   status: T       the status bar's message
//   header: A | B   a table's or tree's column titles
//   row: a | b      a row in view from the top, 8 at most (a table's row title first when it shows them)
//   item: T         a list's item in view, 8 at most ("[x] T" when checkable)
//   text: T         a line of a text view in view, 40 at most
//   code: T         a line of a code editor in view, 40 at most; then   note: T   its annotation (a diagnostic)
//   plot: X,Y WxH   a plot area (a QCustomPlot axis rect) in the PNG's pixels, clipped to the picture
//   axis: T         a plot axis's label               legend: T    a plot legend's entry
//   plot-text: T    a text element or text item on a plot
#pragma once

#include "tour_shot.h"

#include <QStringList>

namespace app {

QStringList shotFacts(const TourShot& shot);

} // namespace app
