// DebugHighlighter: parser events to editor markers.
#include "debug_highlighter.h"

#include "drive_connection.h"
#include "drive/line_locator.h"
#include "main_window.h"

#include "editor/program_editor.h"

namespace app {

namespace {
QStringList linesOf(const QsciScintilla& editor) {
    QStringList lines = editor.text().split(QLatin1Char('\n'));
    for (QString& line : lines)
        if (line.endsWith(QLatin1Char('\r'))) line.chop(1);
    return lines;
}
} // namespace

DebugHighlighter::DebugHighlighter(MainWindow& window, QObject* parent) : QObject(parent), m_window(window) {
    connect(&window.connection(), &DriveConnection::rawReceived, this, &DebugHighlighter::feed);
    connect(&window.connection(), &DriveConnection::linkChanged, this, &DebugHighlighter::reset);
    // The step mark is the BDS5 session's: another family's workspace may show the same editor next.
    connect(&window, &MainWindow::familyChanged, this, [this](drive_core::DriveFamily family) {
        if (family != drive_core::DriveFamily::Bds5) reset();
    });
}

void DebugHighlighter::setColour(const QColor& colour) {
    m_colour = colour;
    if (m_marked) m_marked->setMarkerBackgroundColor(colour, kLineMarker);
}

void DebugHighlighter::feed(const QByteArray& bytes) {
    for (const StepTraceParser::Event& event : m_parser.feed(bytes)) handle(event);
}

void DebugHighlighter::reset() {
    m_parser.reset();
    m_searchFrom = -1;
    clear();
}

void DebugHighlighter::handle(const StepTraceParser::Event& event) {
    using Kind = StepTraceParser::Event::Kind;
    QsciScintilla* editor = m_window.editor();
    switch (event.kind) {
    case Kind::Started:
        // RUN n starts at label n$: look from there (RUN alone from the top).
        m_searchFrom = -1;
        if (editor && event.label >= 0) {
            const int label = LineLocator::labelLine(linesOf(*editor), event.label);
            if (label >= 0) m_searchFrom = label - 1;
        }
        clear();
        break;
    case Kind::AboutToRun: {
        if (!editor) return;
        const int line = LineLocator::find(linesOf(*editor), event.text, m_searchFrom);
        if (line < 0) return clear(); // not in this editor: mark nothing rather than a wrong line
        m_searchFrom = line;
        mark(line, event.stepping);
        break;
    }
    case Kind::Paused:
        break; // monitor mode: the program waits where it was (chosen: keep the mark)
    case Kind::Ended:
        m_searchFrom = -1;
        clear();
        break;
    }
}

void DebugHighlighter::mark(int line, bool stepping) {
    QsciScintilla* editor = m_window.editor();
    if (m_marked && m_marked != editor) clear();
    if (m_marked != editor) {
        editor->markerDefine(QsciScintilla::Background, kLineMarker);
        editor->setMarkerBackgroundColor(m_colour, kLineMarker);
        editor->markerDefine(QsciScintilla::RightArrow, kArrowMarker);
        editor->setMarkerBackgroundColor(QColor(0xd9, 0x8c, 0x00), kArrowMarker);
        editor->setMarkerForegroundColor(QColor(0x80, 0x50, 0x00), kArrowMarker);
        m_marked = editor;
    }
    editor->markerDeleteAll(kLineMarker);
    editor->markerDeleteAll(kArrowMarker);
    editor->markerAdd(line, kLineMarker);
    editor->markerAdd(line, kArrowMarker);
    editor->ensureLineVisible(line);
    m_line = line;
    emit lineHighlighted(line, stepping);
}

void DebugHighlighter::clear() {
    if (m_marked) {
        m_marked->markerDeleteAll(kLineMarker);
        m_marked->markerDeleteAll(kArrowMarker);
    }
    if (m_line < 0) return;
    m_line = -1;
    emit highlightCleared();
}

} // namespace app
