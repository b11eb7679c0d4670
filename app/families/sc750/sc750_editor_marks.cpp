// Sc750 editor marks: marker, indicator and annotation set-up, and the compile error's display.
#include "sc750_editor_marks.h"

#include <Qsci/qsciscintilla.h>
#include <Qsci/qscistyle.h>

#include <QCoreApplication>

namespace app {

namespace {
constexpr int kErrorIndicator = 20;     // as Bds5Diagnostics: one squiggle for the drive's errors
constexpr int kErrorLineIndicator = 22; // the whole offending line, drawn over the caret line (a marker is not)
const char* kPreparedProperty = "sc750Prepared";
} // namespace

bool defineSc750Marks(QsciScintilla& editor) {
    if (editor.property(kPreparedProperty).toBool()) return false;
    editor.setProperty(kPreparedProperty, true);
    editor.markerDefine(QsciScintilla::Background, kSc750CurrentLineMarker);
    editor.setMarkerBackgroundColor(QColor(0xff, 0xe0, 0x8a), kSc750CurrentLineMarker);
    editor.markerDefine(QsciScintilla::RightArrow, kSc750ArrowMarker);
    editor.setMarkerBackgroundColor(QColor(0xd9, 0x8c, 0x00), kSc750ArrowMarker);
    editor.setMarkerForegroundColor(QColor(0x80, 0x50, 0x00), kSc750ArrowMarker);
    editor.markerDefine(QsciScintilla::Circle, kSc750BreakpointMarker);
    editor.setMarkerBackgroundColor(QColor(0xd1, 0x24, 0x2f), kSc750BreakpointMarker);
    editor.setMarkerForegroundColor(QColor(0x9f, 0x1c, 0x24), kSc750BreakpointMarker);
    editor.markerDefine(QsciScintilla::Background, kSc750ErrorMarker);
    editor.setMarkerBackgroundColor(QColor(0xff, 0xd7, 0xd4), kSc750ErrorMarker);
    editor.setMarginType(kSc750MarkerMargin, QsciScintilla::SymbolMargin);
    editor.setMarginWidth(kSc750MarkerMargin, 18);
    editor.setMarginMarkerMask(kSc750MarkerMargin, editor.marginMarkerMask(kSc750MarkerMargin) |
                                                       (1 << kSc750BreakpointMarker) | (1 << kSc750ArrowMarker));
    editor.setMarginSensitivity(kSc750MarkerMargin, true);
    editor.indicatorDefine(QsciScintilla::SquiggleLowIndicator, kErrorIndicator);
    editor.setIndicatorForegroundColor(QColor(0xd1, 0x24, 0x2f), kErrorIndicator);
    editor.indicatorDefine(QsciScintilla::StraightBoxIndicator, kErrorLineIndicator);
    editor.setIndicatorForegroundColor(QColor(0xff, 0x5a, 0x4f, 60), kErrorLineIndicator);
    editor.SendScintilla(QsciScintilla::SCI_INDICSETOUTLINEALPHA, static_cast<unsigned long>(kErrorLineIndicator), 0L);
    editor.setAnnotationDisplay(QsciScintilla::AnnotationBoxed);
    return true;
}

void showCompileError(QsciScintilla& editor, const drive_core::sc750::CompileError& error) {
    const int line = qBound(0, error.line - 1, qMax(0, editor.lines() - 1));
    const int column = qMax(0, error.column - 1);
    editor.markerAdd(line, kSc750ErrorMarker);
    editor.annotate(line,
                    QCoreApplication::translate("app::Sc750Debugger", "Col %1: %2")
                        .arg(error.column)
                        .arg(QString::fromStdString(error.message)),
                    QsciStyle(-1, QStringLiteral("SC750 compile error"), QColor(0x9f, 0x1c, 0x24),
                              QColor(0xff, 0xf0, 0xef), editor.font(), true));
    const long start = editor.positionFromLineIndex(line, column);
    const long length = qMax(1L, long(error.near.size()));
    editor.SendScintilla(QsciScintilla::SCI_SETINDICATORCURRENT, kErrorIndicator);
    editor.SendScintilla(QsciScintilla::SCI_INDICATORFILLRANGE, start, length);
    const long lineStart = editor.SendScintilla(QsciScintilla::SCI_POSITIONFROMLINE, line);
    const long lineEnd = editor.SendScintilla(QsciScintilla::SCI_GETLINEENDPOSITION, line);
    editor.SendScintilla(QsciScintilla::SCI_SETINDICATORCURRENT, kErrorLineIndicator);
    editor.SendScintilla(QsciScintilla::SCI_INDICATORFILLRANGE, lineStart, qMax(1L, lineEnd - lineStart));
    editor.setCursorPosition(line, column);
    editor.ensureLineVisible(line);
    editor.setFocus();
}

void clearCompileError(QsciScintilla& editor) {
    editor.markerDeleteAll(kSc750ErrorMarker);
    editor.clearAnnotations();
    for (const int indicator : {kErrorIndicator, kErrorLineIndicator}) {
        editor.SendScintilla(QsciScintilla::SCI_SETINDICATORCURRENT, indicator);
        editor.SendScintilla(QsciScintilla::SCI_INDICATORCLEARRANGE, 0, editor.length());
    }
}

} // namespace app
