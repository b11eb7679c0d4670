// TransferMarkers: background markers and annotations.
#include "transfer_markers.h"

#include <Qsci/qsciscintilla.h>
#include <Qsci/qscistyle.h>

#include <QList>

namespace app {

namespace {
const QColor kErrorLine(0xfd, 0xe7, 0xe9);
const QColor kMismatchLine(0xff, 0xf4, 0xd6);

// One annotation style per editor, allocated on first use (QsciStyle(-1) takes the next free number).
const QsciStyle& annotationStyle(QsciScintilla& editor) {
    static QsciStyle style(-1, QStringLiteral("drive error annotation"), QColor(0xb3, 0x26, 0x1e),
                           QColor(0xfd, 0xf3, 0xf3), editor.font());
    return style;
}

void defineMarkers(QsciScintilla& editor) {
    editor.markerDefine(QsciScintilla::Background, TransferMarkers::kErrorMarker);
    editor.setMarkerBackgroundColor(kErrorLine, TransferMarkers::kErrorMarker);
    editor.markerDefine(QsciScintilla::Background, TransferMarkers::kMismatchMarker);
    editor.setMarkerBackgroundColor(kMismatchLine, TransferMarkers::kMismatchMarker);
    editor.setAnnotationDisplay(QsciScintilla::AnnotationBoxed);
}
} // namespace

void TransferMarkers::mark(QsciScintilla& editor, int line, const QString& text, Kind kind) {
    if (line < 1 || line > editor.lines()) return;
    defineMarkers(editor);
    const int at = line - 1;
    editor.markerAdd(at, kind == Kind::Error ? kErrorMarker : kMismatchMarker);
    const QString before = annotationAt(editor, line);
    if (before.split(QLatin1Char('\n')).contains(text)) return;
    editor.annotate(at, before.isEmpty() ? text : before + QLatin1Char('\n') + text, annotationStyle(editor));
}

void TransferMarkers::clear(QsciScintilla& editor) {
    for (const int line : markedLines(editor))
        editor.clearAnnotations(line - 1);
    editor.markerDeleteAll(kErrorMarker);
    editor.markerDeleteAll(kMismatchMarker);
}

QList<int> TransferMarkers::markedLines(QsciScintilla& editor) {
    QList<int> lines;
    const unsigned mask = (1u << kErrorMarker) | (1u << kMismatchMarker);
    for (int at = editor.markerFindNext(0, mask); at >= 0; at = editor.markerFindNext(at + 1, mask))
        lines.append(at + 1);
    return lines;
}

QString TransferMarkers::annotationAt(QsciScintilla& editor, int line) {
    return editor.annotation(line - 1);
}

} // namespace app
