// BlockMarker: a start mark that follows edits, and the selection it makes.
#include "block_marker.h"

#include <Qsci/qsciscintilla.h>

namespace editor {

BlockMarker& BlockMarker::of(QsciScintilla& editor) {
    if (auto* existing = editor.findChild<BlockMarker*>(QString(), Qt::FindDirectChildrenOnly)) return *existing;
    return *new BlockMarker(editor);
}

BlockMarker::BlockMarker(QsciScintilla& editor) : QObject(&editor), m_editor(editor) {
    connect(&editor, &QsciScintillaBase::SCN_MODIFIED, this,
            [this](int position, int type, const char*, int length, int, int, int, int, int, int) {
                follow(position, type, length);
            });
}

void BlockMarker::markStart() {
    m_start = m_editor.SendScintilla(QsciScintilla::SCI_GETCURRENTPOS);
    m_editor.SendScintilla(QsciScintilla::SCI_SETEMPTYSELECTION, m_start);
}

bool BlockMarker::markEnd() {
    if (m_start < 0) return false;
    const long caret = m_editor.SendScintilla(QsciScintilla::SCI_GETCURRENTPOS);
    m_editor.SendScintilla(QsciScintilla::SCI_SETSEL, m_start, caret);
    return true;
}

void BlockMarker::follow(int position, int type, int length) {
    if (m_start < 0) return;
    if ((type & QsciScintilla::SC_MOD_INSERTTEXT) && position <= m_start) m_start += length;
    if ((type & QsciScintilla::SC_MOD_DELETETEXT) && position < m_start)
        m_start -= qMin<long>(length, m_start - position);
}

} // namespace editor
