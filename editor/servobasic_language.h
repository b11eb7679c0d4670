// ServoBasicLanguage: what makes a ProgramEditor a ServoBASIC Plus editor, owned by that editor — the
// lexer, completion of catalog names (after two letters, or Ctrl+Space) and F1 help from the SC750 catalog
// in a popup (L880-L916: cursor on a keyword, F1). Installed on every .bas tab by Sc750Workspace.
// GUI thread only.
#pragma once

#include "language_support.h"

namespace editor {

class ServoBasicLexer;

class ServoBasicLanguage final : public LanguageSupport {
    Q_OBJECT
public:
    static constexpr int kCompletionListId = 52; // showUserList id (the BDS5's is 51)
    static constexpr int kCompletionMinLetters = 2;

    // Installs ServoBASIC support in editor (once; later calls return the same object).
    static ServoBasicLanguage* install(ProgramEditor& editor) { return installIn<ServoBasicLanguage>(editor); }
    // The support installed in editor, or nullptr.
    static ServoBasicLanguage* of(const QsciScintilla* editor) { return find<ServoBasicLanguage>(editor); }
    // Takes it out again (the tab became another type); the editor's lexer goes when it is ours.
    static void uninstall(ProgramEditor& editor) { uninstallFrom<ServoBasicLanguage>(editor); }

    ServoBasicLexer* lexer() const { return m_lexer; }

    // The catalog names that start with the word before the cursor, as Scintilla's list (Ctrl+Space, or
    // after two letters; the same list either way). False when none.
    bool showCompletions(bool explicitRequest) override;
    // The word being typed; empty in a comment or a string.
    QString wordBeforeCursor() const;

protected:
    void detach() override;

private:
    friend class LanguageSupport;
    explicit ServoBasicLanguage(ProgramEditor& editor);
    void completionChosen(int id, const QString& text);

    ServoBasicLexer* m_lexer;
};

} // namespace editor
