// DebugHighlighter: while the drive single-steps or traces, marks in the current editor the line about to
// run — mapped from the text the drive shows before its s--> prompt or after t... — and clears the mark
// when the drive is back at its interactive prompt, or another family is chosen. Asks MainWindow for the
// editor each time (tabs).
#pragma once

#include "step_trace_parser.h"

#include <QColor>
#include <QObject>
#include <QPointer>

class QsciScintilla;

namespace app {

class MainWindow;

class DebugHighlighter final : public QObject {
    Q_OBJECT
public:
    // Marker numbers in the editor: a background for the line and an arrow in the symbol margin.
    static constexpr int kLineMarker = 24; // 20-21 diagnostics, 22-23 transfer errors
    static constexpr int kArrowMarker = 25;

    explicit DebugHighlighter(MainWindow& window, QObject* parent = nullptr);

    // The highlighted line (0-based) in the editor that shows it, or -1.
    int currentLine() const { return m_line; }
    void setColour(const QColor& colour);

    // Bytes from the drive (connected to DriveConnection::rawReceived).
    void feed(const QByteArray& bytes);
    void reset();

signals:
    void lineHighlighted(int line, bool stepping); // 0-based
    void highlightCleared();

private:
    void handle(const StepTraceParser::Event& event);
    void mark(int line, bool stepping);
    void clear();

    MainWindow& m_window;
    StepTraceParser m_parser;
    QPointer<QsciScintilla> m_marked; // the editor that carries the marks
    int m_line = -1;
    int m_searchFrom = -1; // the next match is looked for after this line
    QColor m_colour{0xff, 0xe0, 0x8a};
};

} // namespace app
