// The modern and classic key tables.
#include "keymap.h"

namespace editor {

namespace {
using C = EditorCommand;

QKeySequence ctrl(Qt::Key key) {
    return QKeySequence(Qt::CTRL | key);
}
QKeySequence ctrl2(Qt::Key first, Qt::Key second) {
    return QKeySequence(Qt::CTRL | first, Qt::CTRL | second);
}
} // namespace

Keymap::Keymap(QString name, std::vector<KeyBinding> bindings)
    : m_name(std::move(name)), m_bindings(std::move(bindings)) {}

Keymap Keymap::modern() {
    // chosen: editor functions Motion Link had but today's editors have no common key for get keys
    // from VS Code (Ctrl+Shift+K delete line) or Scintilla's own (Ctrl+Shift+Delete to end of line).
    return Keymap(kModern, {
                               {C::NewFile, QKeySequence::New},
                               {C::OpenFile, QKeySequence::Open},
                               {C::SaveFile, QKeySequence::Save},
                               {C::SaveFileAs, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S)},
                               {C::CloseTab, ctrl(Qt::Key_W)},
                               {C::Print, QKeySequence::Print},
                               {C::Undo, QKeySequence::Undo},
                               {C::Redo, ctrl(Qt::Key_Y)},
                               {C::Redo, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z)},
                               {C::CopyBlock, QKeySequence::Copy},
                               {C::CutBlock, QKeySequence::Cut},
                               {C::PasteBlock, QKeySequence::Paste},
                               {C::Find, QKeySequence::Find},
                               {C::FindNext, QKeySequence(Qt::Key_F3)},
                               {C::FindPrevious, QKeySequence(Qt::SHIFT | Qt::Key_F3)},
                               {C::Replace, ctrl(Qt::Key_H)},
                               {C::GoToLine, ctrl(Qt::Key_G)},
                               {C::DeleteWord, ctrl(Qt::Key_Delete)},
                               {C::DeleteToEndOfLine, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Delete)},
                               {C::DeleteLine, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_K)},
                               {C::UndeleteLine, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_U)},
                               {C::InsertLine, QKeySequence(Qt::CTRL | Qt::Key_Return)},
                           });
}

Keymap Keymap::classic() {
    // Motion Link's own keys (manual L1133-1188). chosen: keys Motion Link did not use keep their modern
    // meaning (Ctrl+O open, Ctrl+W close tab, Ctrl+Z undo, F3 repeat find), so nothing is lost by
    // switching; ^C and ^X are WordStar's page down and line down here, as Table 2.1 lists them.
    return Keymap(kClassic, {
                                {C::SaveFile, ctrl2(Qt::Key_K, Qt::Key_S)},
                                {C::MergeFile, ctrl2(Qt::Key_K, Qt::Key_R)},
                                {C::Print, ctrl(Qt::Key_P)},
                                {C::MenuBar, QKeySequence(Qt::Key_F10)},
                                {C::OpenFile, QKeySequence::Open},
                                {C::SaveFileAs, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S)},
                                {C::CloseTab, ctrl(Qt::Key_W)},
                                {C::Undo, QKeySequence::Undo},
                                {C::Redo, QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z)},
                                {C::MarkBlockStart, ctrl2(Qt::Key_K, Qt::Key_B)},
                                {C::MarkBlockEnd, ctrl2(Qt::Key_K, Qt::Key_K)},
                                {C::CopyBlock, ctrl2(Qt::Key_K, Qt::Key_C)},
                                {C::CutBlock, ctrl2(Qt::Key_K, Qt::Key_V)},
                                {C::PasteBlock, ctrl2(Qt::Key_K, Qt::Key_P)},
                                {C::SaveBlock, ctrl2(Qt::Key_K, Qt::Key_W)},
                                {C::Find, ctrl2(Qt::Key_Q, Qt::Key_F)},
                                {C::FindNext, ctrl(Qt::Key_L)},
                                {C::FindNext, QKeySequence(Qt::Key_F3)},
                                {C::Replace, ctrl2(Qt::Key_Q, Qt::Key_A)},
                                {C::GoToLine, ctrl2(Qt::Key_Q, Qt::Key_I)},
                                {C::ShowSize, ctrl2(Qt::Key_Q, Qt::Key_O)},
                                {C::DeleteWord, ctrl(Qt::Key_T)},
                                {C::DeleteToEndOfLine, ctrl2(Qt::Key_Q, Qt::Key_Y)},
                                {C::DeleteLine, ctrl(Qt::Key_Y)},
                                {C::UndeleteLine, ctrl(Qt::Key_U)},
                                {C::InsertLine, ctrl(Qt::Key_N)},
                                {C::DeleteEntireEditor, ctrl2(Qt::Key_K, Qt::Key_Y)},
                                {C::DocumentStart, ctrl(Qt::Key_PageUp)},
                                {C::DocumentEnd, ctrl(Qt::Key_PageDown)},
                                {C::PageUp, ctrl(Qt::Key_R)},
                                {C::PageDown, ctrl(Qt::Key_C)},
                                {C::CursorUp, ctrl(Qt::Key_E)},
                                {C::CursorDown, ctrl(Qt::Key_X)},
                                {C::WordLeft, ctrl(Qt::Key_A)},
                                {C::WordRight, ctrl(Qt::Key_F)},
                                {C::CursorLeft, ctrl(Qt::Key_S)},
                                {C::CursorRight, ctrl(Qt::Key_D)},
                            });
}

Keymap Keymap::named(const QString& name) {
    return name == kClassic ? classic() : modern();
}

QList<QKeySequence> Keymap::keysFor(EditorCommand command) const {
    QList<QKeySequence> keys;
    for (const KeyBinding& binding : m_bindings)
        if (binding.command == command) keys.append(binding.keys);
    return keys;
}

std::optional<EditorCommand> Keymap::commandFor(const QKeySequence& keys) const {
    for (const KeyBinding& binding : m_bindings)
        if (binding.keys == keys) return binding.command;
    return std::nullopt;
}

bool Keymap::isPrefix(const QKeySequence& keys) const {
    for (const KeyBinding& binding : m_bindings)
        if (keys.matches(binding.keys) == QKeySequence::PartialMatch) return true;
    return false;
}

bool Keymap::isCursorCommand(EditorCommand command) {
    return command >= C::CursorUp;
}

QString Keymap::caretNotation(const QKeySequence& keys) {
    QString text;
    for (int i = 0; i < keys.count(); ++i) {
        const QKeyCombination combination = keys[i];
        const Qt::Key key = combination.key();
        if (combination.keyboardModifiers() == Qt::ControlModifier && key >= Qt::Key_A && key <= Qt::Key_Z)
            text += QLatin1Char('^') + QChar(char16_t(key));
        else
            text += QKeySequence(combination).toString(QKeySequence::PortableText);
    }
    return text;
}

} // namespace editor
