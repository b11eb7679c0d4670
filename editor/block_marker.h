// Motion Link's marked block (^K^B start, ^K^K end; manual L1142-1147) on a QScintilla editor. The block
// IS the selection, so mouse and Shift+arrows mark blocks too; the start mark only remembers where ^K^B
// was pressed — it follows the text as lines are inserted or deleted above it. GUI thread only.
#pragma once

#include <QObject>

class QsciScintilla;

namespace editor {

class BlockMarker final : public QObject {
    Q_OBJECT
public:
    // The editor's marker, created on first use and owned by the editor.
    static BlockMarker& of(QsciScintilla& editor);

    // MARK START OF BLOCK: remembers the cursor position (and clears any selection).
    void markStart();
    // MARK END OF BLOCK: selects from the start mark to the cursor; false when no start is marked.
    bool markEnd();
    bool hasStart() const { return m_start >= 0; }
    // The start mark as a byte position in the document, or -1.
    long startPosition() const { return m_start; }

private:
    explicit BlockMarker(QsciScintilla& editor);
    void follow(int position, int type, int length);

    QsciScintilla& m_editor;
    long m_start = -1;
};

} // namespace editor
