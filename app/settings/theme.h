// Theme: the light and dark colours of the terminal and the program editor. The editor's own (light)
// colours are remembered on the editor the first time it turns dark, so light puts back exactly what the
// editor and its lexer chose. Call applyToEditor for every editor (tabs) when it is created.
#pragma once

#include "app_options.h"

#include <QColor>

class QLabel;
class QsciScintilla;

namespace app {

class TerminalWidget;

class Theme {
public:
    static void applyToTerminal(TerminalWidget& terminal, AppOptions::Theme theme);
    static void applyToEditor(QsciScintilla& editor, AppOptions::Theme theme);
    // The background of the line about to run while single-stepping or tracing.
    static QColor stepHighlight(AppOptions::Theme theme);
    // A colour readable on the dark background with the same hue (dark text becomes light).
    static QColor forDarkBackground(const QColor& colour);
    // A dialog's or a dock's status line: the text, in red when it reports a refusal or an error.
    static void showStatus(QLabel& label, const QString& text, bool error);
};

} // namespace app
