// KeyChordFilter: runs a Keymap inside the editors it watches. It claims the keys its keymap binds
// before QScintilla or a window shortcut can (ShortcutOverride), collects two-key chords (^K then B or
// ^B), moves the cursor itself for the cursor commands, and reports every other command. Keys outside
// the keymap pass through untouched. GUI thread only.
#pragma once

#include "keymap.h"

#include <QKeySequence>
#include <QObject>

class QKeyEvent;
class QsciScintilla;

namespace editor {

class KeyChordFilter final : public QObject {
    Q_OBJECT
public:
    explicit KeyChordFilter(QObject* parent = nullptr);

    void setKeymap(const Keymap& keymap);
    const Keymap& keymap() const { return m_keymap; }
    // Starts filtering the editor's keys (until it is destroyed).
    void watch(QsciScintilla* editor);

signals:
    // A non-cursor command was typed in editor.
    void commandTriggered(editor::EditorCommand command, QsciScintilla* editor);
    // The first key of a chord is waiting for its second ("^K"); empty when no chord is pending.
    void pendingChanged(const QString& keys);
    // A chord that means nothing ("^K^Z"); it was swallowed.
    void unknownChord(const QString& keys);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    bool claims(const QKeyEvent& key) const;
    bool handle(QsciScintilla& editor, const QKeyEvent& key);
    void moveCursor(QsciScintilla& editor, EditorCommand command);
    void setPending(const QKeySequence& keys);

    Keymap m_keymap;
    QKeySequence m_pending;
};

} // namespace editor
