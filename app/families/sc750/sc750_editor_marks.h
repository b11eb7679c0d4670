// The marks Motion Dialogue puts in a program editor: breakpoint dots in the symbol margin, the current
// (stopped-at) line, and the first compile error — its line, the text it was near and the compiler's
// message under the line (L2632-L2646). Free functions over QsciScintilla; GUI thread only.
#pragma once

#include "drive_core/sc750/sc750_error.h"

class QsciScintilla;

namespace app {

// Marker numbers: BDS5 diagnostics use 20-21 (the error marker is shared: one family's errors at a
// time), the BDS5 transfer 22-23; 24-25 are the current line as DebugHighlighter's; 26 the breakpoint.
inline constexpr int kSc750ErrorMarker = 20;
inline constexpr int kSc750CurrentLineMarker = 24;
inline constexpr int kSc750ArrowMarker = 25;
inline constexpr int kSc750BreakpointMarker = 26;
inline constexpr int kSc750MarkerMargin = 1;

// Defines the markers, indicators and the clickable margin once per editor; false when done before.
bool defineSc750Marks(QsciScintilla& editor);
// Marks the error's line and text, shows the message under the line and puts the cursor at the error.
void showCompileError(QsciScintilla& editor, const drive_core::sc750::CompileError& error);
void clearCompileError(QsciScintilla& editor);

} // namespace app
