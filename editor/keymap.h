// The editor's two keymaps: "modern" (Ctrl+F, Ctrl+H, Ctrl+G, Ctrl+S ...) and "classic", Motion Link's
// WordStar-like keys (^K^B, ^Q^F, ^L, ^Y ..., manual L1133-1188). A keymap is data: which key sequence
// runs which EditorCommand. The QSettings key kKeymapSettingsKey names the one in use. Any thread.
#pragma once

#include <QKeySequence>
#include <QList>
#include <QString>

#include <optional>
#include <vector>

namespace editor {

enum class EditorCommand {
    // File
    NewFile,
    OpenFile,
    SaveFile,
    SaveFileAs,
    CloseTab,
    MergeFile,
    Print,
    MenuBar,
    // Edit (the block is the selection)
    Undo,
    Redo,
    MarkBlockStart,
    MarkBlockEnd,
    CopyBlock,
    CutBlock,
    PasteBlock,
    SaveBlock,
    // Goto
    Find,
    FindNext,
    FindPrevious,
    Replace,
    GoToLine,
    ShowSize,
    // Insert/Delete
    DeleteWord,
    DeleteToEndOfLine,
    DeleteLine,
    UndeleteLine,
    InsertLine,
    DeleteEntireEditor,
    // Cursor keys (Table 2.1); handled inside the editor, never menu items
    CursorUp,
    CursorDown,
    CursorLeft,
    CursorRight,
    WordLeft,
    WordRight,
    PageUp,
    PageDown,
    DocumentStart,
    DocumentEnd,
};

struct KeyBinding {
    EditorCommand command;
    QKeySequence keys;
};

class Keymap {
public:
    static inline const QString kSettingsKey = QStringLiteral("editor/keymap");
    static inline const QString kModern = QStringLiteral("modern");
    static inline const QString kClassic = QStringLiteral("classic");

    static Keymap modern();
    static Keymap classic();
    // The keymap called name; an unknown name gives the modern one.
    static Keymap named(const QString& name);

    QString name() const { return m_name; }
    const std::vector<KeyBinding>& bindings() const { return m_bindings; }
    // Every sequence bound to command, first the one menus show; empty when unbound.
    QList<QKeySequence> keysFor(EditorCommand command) const;
    // The command typed keys run exactly, if any.
    std::optional<EditorCommand> commandFor(const QKeySequence& keys) const;
    // True when keys is the start of a longer bound sequence (^K of ^K^B).
    bool isPrefix(const QKeySequence& keys) const;

    static bool isCursorCommand(EditorCommand command);
    // Motion Link's notation: Ctrl+K, Ctrl+B -> "^K^B"; other keys in Qt's portable text ("F10").
    static QString caretNotation(const QKeySequence& keys);

private:
    Keymap(QString name, std::vector<KeyBinding> bindings);

    QString m_name;
    std::vector<KeyBinding> m_bindings;
};

} // namespace editor
