// ServoBasicLanguage: what makes a ProgramEditor a ServoBASIC Plus editor, owned by that editor — the
// lexer, completion of catalog names (after two letters, or Ctrl+Space) and F1 help from the SC750 catalog
// in a popup (L880-L916: cursor on a keyword, F1). Installed on every .bas tab by Sc750Workspace.
// GUI thread only.
#pragma once

#include <QObject>
#include <QString>

namespace editor {
class HelpPopup;
class ProgramEditor;
}

namespace app {

class ServoBasicLexer;

class ServoBasicLanguage final : public QObject {
    Q_OBJECT
public:
    // Installs ServoBASIC support in editor (once; later calls return the same object).
    static ServoBasicLanguage* install(editor::ProgramEditor& editor);
    static ServoBasicLanguage* of(const editor::ProgramEditor& editor);
    // Takes it out again (the tab became another type); the editor's lexer goes when it is ours.
    static void uninstall(editor::ProgramEditor& editor);

    // The catalog entry for a word as HTML ("GO.VEL", "run.speed", "MID$"); empty when unknown.
    static QString helpHtml(const QString& word);
    // The word under (or just before) the cursor; empty when none.
    QString wordAtCursor() const;
    // F1: shows the help for the word at the cursor. Returns the word (empty: nothing shown).
    QString showHelpAtCursor();
    void hideHelp();
    // The catalog names that start with the word before the cursor, as Scintilla's list (Ctrl+Space, or
    // after two letters). False when none.
    bool showCompletions();
    QString wordBeforeCursor() const;

    static constexpr int kCompletionListId = 52; // showUserList id (the BDS5's is 51)
    static constexpr int kCompletionMinLetters = 2;
    editor::HelpPopup* helpPopup() const { return m_help; }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    explicit ServoBasicLanguage(editor::ProgramEditor& editor);
    void completionChosen(int id, const QString& text);

    editor::ProgramEditor& m_editor;
    ServoBasicLexer* m_lexer;
    editor::HelpPopup* m_help;
};

} // namespace app
