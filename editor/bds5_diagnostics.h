// Bds5Diagnostics: the drive's own verdict on the program as you type. A short while after the last change
// it runs drive_core::bds5::checkProgram (the simulator's lexer and interpreter) over the editor's text and
// shows each error as a margin marker, a squiggle under the entry, and an annotation under the line with
// the drive's text (`ERR 83 '2'  BAD OR OUT OF RANGE`). GUI thread only; owned by its editor.
#pragma once

#include "drive_core/bds5/bds5_checker.h"

#include <QObject>
#include <QString>
#include <QTimer>

#include <Qsci/qscistyle.h>

#include <utility>
#include <vector>

class QsciScintilla;

namespace editor {

class Bds5Diagnostics final : public QObject {
    Q_OBJECT
public:
    static constexpr int kDebounceMs = 250; // after the last change
    // Margin 1 shows the markers; marker and indicator numbers are reserved for diagnostics.
    static constexpr int kMarkerMargin = 1;
    static constexpr int kErrorMarker = 20;
    static constexpr int kAdviceMarker = 21;
    static constexpr int kErrorIndicator = 20;
    static constexpr int kAdviceIndicator = 21;

    // Becomes a child of editor and starts watching its text (a first check runs after the debounce).
    explicit Bds5Diagnostics(QsciScintilla& editor);

    // The drive's message for one diagnostic, as the annotation shows it.
    static QString annotationText(const drive_core::bds5::Diagnostic& d);
    // The editor's text as the lines checkProgram takes (UTF-8, without line ends).
    static std::vector<std::string> programLines(const QString& text);

    // Takes every marker, squiggle and annotation off the editor and stops checking until the next edit.
    void clear();
    // Checks now instead of after the debounce (tests, benchmarks, before a download).
    void checkNow();
    // Shows these diagnostics (replacing the previous ones). Public so a benchmark can time it alone.
    void show(std::vector<drive_core::bds5::Diagnostic> diagnostics);

    const std::vector<drive_core::bds5::Diagnostic>& diagnostics() const { return m_diagnostics; }
    int errorCount() const { return m_errors; }
    int adviceCount() const { return int(m_diagnostics.size()) - m_errors; }
    bool pending() const { return m_timer.isActive(); }
    // 0-based editor lines of the diagnostics, in order; -1 when none after `afterLine`.
    int nextLine(int afterLine) const;

    void setDarkTheme(bool dark);

signals:
    // After every check whose result differs from the one shown.
    void changed(int errors, int advice);

private:
    void defineMarkers();
    // Takes our rows out of the annotations we added, leaving anyone else's.
    void removeShownAnnotations();

    QsciScintilla& m_editor;
    QTimer m_timer;
    std::vector<drive_core::bds5::Diagnostic> m_diagnostics;
    std::vector<std::pair<int, QString>> m_shown; // marker handle of each annotated line, our rows there
    int m_errors = 0;
    bool m_checkedOnce = false;
    QsciStyle m_errorStyle;
    QsciStyle m_adviceStyle;
};

} // namespace editor
