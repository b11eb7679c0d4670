// KeyChordFilter: key claiming, chord collection and cursor moves.
#include "key_chord_filter.h"

#include <Qsci/qsciscintilla.h>

#include <QKeyEvent>

namespace editor {

namespace {
bool isModifierKey(int key) {
    return key == Qt::Key_Control || key == Qt::Key_Shift || key == Qt::Key_Alt || key == Qt::Key_Meta ||
           key == Qt::Key_AltGr || key == Qt::Key_unknown;
}

QKeyCombination combinationOf(const QKeyEvent& key) {
    return QKeyCombination(key.modifiers() & ~Qt::KeypadModifier, Qt::Key(key.key()));
}

QKeySequence appended(const QKeySequence& pending, QKeyCombination next) {
    if (pending.isEmpty()) return QKeySequence(next);
    return QKeySequence(pending[0], next);
}
} // namespace

KeyChordFilter::KeyChordFilter(QObject* parent) : QObject(parent), m_keymap(Keymap::modern()) {}

void KeyChordFilter::setKeymap(const Keymap& keymap) {
    m_keymap = keymap;
    setPending({});
}

void KeyChordFilter::watch(QsciScintilla* editor) {
    editor->installEventFilter(this);
}

bool KeyChordFilter::eventFilter(QObject* watched, QEvent* event) {
    auto* editor = qobject_cast<QsciScintilla*>(watched);
    if (!editor) return false;
    switch (event->type()) {
    case QEvent::ShortcutOverride:
        if (claims(*static_cast<QKeyEvent*>(event))) {
            event->accept();
            return true;
        }
        return false;
    case QEvent::KeyPress: return handle(*editor, *static_cast<QKeyEvent*>(event));
    case QEvent::FocusOut: setPending({}); return false;
    default: return false;
    }
}

bool KeyChordFilter::claims(const QKeyEvent& key) const {
    if (isModifierKey(key.key())) return false;
    if (!m_pending.isEmpty()) return true; // the second key of a chord is ours, whatever it is
    const QKeySequence typed(combinationOf(key));
    return m_keymap.commandFor(typed) || m_keymap.isPrefix(typed);
}

bool KeyChordFilter::handle(QsciScintilla& editor, const QKeyEvent& key) {
    if (isModifierKey(key.key())) return false;
    const bool chordPending = !m_pending.isEmpty();
    QKeySequence typed = appended(m_pending, combinationOf(key));
    std::optional<EditorCommand> command = m_keymap.commandFor(typed);
    // WordStar accepts the second key of a chord with or without Ctrl: ^K B is ^K^B.
    if (!command && chordPending && key.modifiers() == Qt::NoModifier)
        command = m_keymap.commandFor(appended(m_pending, QKeyCombination(Qt::ControlModifier, Qt::Key(key.key()))));
    if (command) {
        setPending({});
        if (Keymap::isCursorCommand(*command))
            moveCursor(editor, *command);
        else
            emit commandTriggered(*command, &editor);
        return true;
    }
    if (!chordPending && m_keymap.isPrefix(typed)) {
        setPending(typed);
        return true;
    }
    if (chordPending) {
        setPending({});
        emit unknownChord(Keymap::caretNotation(typed));
        return true;
    }
    return false;
}

void KeyChordFilter::moveCursor(QsciScintilla& editor, EditorCommand command) {
    int message = 0;
    switch (command) {
    case EditorCommand::CursorUp: message = QsciScintilla::SCI_LINEUP; break;
    case EditorCommand::CursorDown: message = QsciScintilla::SCI_LINEDOWN; break;
    case EditorCommand::CursorLeft: message = QsciScintilla::SCI_CHARLEFT; break;
    case EditorCommand::CursorRight: message = QsciScintilla::SCI_CHARRIGHT; break;
    case EditorCommand::WordLeft: message = QsciScintilla::SCI_WORDLEFT; break;
    case EditorCommand::WordRight: message = QsciScintilla::SCI_WORDRIGHT; break;
    case EditorCommand::PageUp: message = QsciScintilla::SCI_PAGEUP; break;
    case EditorCommand::PageDown: message = QsciScintilla::SCI_PAGEDOWN; break;
    case EditorCommand::DocumentStart: message = QsciScintilla::SCI_DOCUMENTSTART; break;
    case EditorCommand::DocumentEnd: message = QsciScintilla::SCI_DOCUMENTEND; break;
    default: return;
    }
    editor.SendScintilla(message);
}

void KeyChordFilter::setPending(const QKeySequence& keys) {
    if (keys == m_pending) return;
    m_pending = keys;
    emit pendingChanged(keys.isEmpty() ? QString() : Keymap::caretNotation(keys));
}

} // namespace editor
