// TransferMarkers: drive errors and verify differences shown in the editor at the line they belong to — a
// tinted line (a Scintilla background marker of its own number) and an annotation under it with the drive's
// words. Works on any QsciScintilla through its public API; clear() removes only these marks.
// GUI thread only.
#pragma once

#include <QString>

class QsciScintilla;

namespace app {

class TransferMarkers {
public:
    enum class Kind { Error, Mismatch };

    // line: 1-based editor line. Adds to what is already shown at that line.
    static void mark(QsciScintilla& editor, int line, const QString& text, Kind kind = Kind::Error);
    static void clear(QsciScintilla& editor);
    // The 1-based lines marked now (for tests and the tour).
    static QList<int> markedLines(QsciScintilla& editor);
    // The annotation under a 1-based line ("" if none).
    static QString annotationAt(QsciScintilla& editor, int line);

    // Scintilla markers 0-24 are free for applications (25-31 are folding); chosen well above the ones
    // editors usually take first.
    static constexpr int kErrorMarker = 22;
    static constexpr int kMismatchMarker = 23;
};

} // namespace app
