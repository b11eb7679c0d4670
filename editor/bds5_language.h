// Bds5Language: everything that makes a ProgramEditor a BDS5 editor, owned by that editor — the lexer
// (colours, folding), diagnostics as you type, completion (after two letters, or Ctrl+Space) and F1 help
// (a popup, plus ProgramEditor::helpRequested). Install once per editor (every tab). GUI thread only.
#pragma once

#include "bds5_lexer.h"
#include "language_support.h"

namespace editor {

class Bds5Diagnostics;

class Bds5Language final : public LanguageSupport {
    Q_OBJECT
public:
    static constexpr int kFoldMargin = 2;
    static constexpr int kCompletionListId = 51; // showUserList id
    static constexpr int kCompletionMinLetters = 2;

    // Installs BDS5 support in editor (once; later calls return the same object).
    static Bds5Language* install(ProgramEditor& editor) { return installIn<Bds5Language>(editor); }
    // The support installed in editor, or nullptr.
    static Bds5Language* of(const QsciScintilla* editor) { return find<Bds5Language>(editor); }
    // Takes it out again (the file became a capture, say): diagnostics, folding, popup and key handling
    // go; the lexer stays with the editor, which may replace it. Nothing happens when none is installed.
    static void uninstall(ProgramEditor& editor) { uninstallFrom<Bds5Language>(editor); }

    Bds5Lexer* lexer() const { return m_lexer; }
    Bds5Diagnostics* diagnostics() const { return m_diagnostics; }

    // Light or dark colours for the text, margins, annotations and popups.
    void setTheme(Bds5Lexer::Theme theme);

    // The completion list for the word before the cursor (explicit: even for fewer than two letters, as
    // Ctrl+Space does). False when nothing matches.
    bool showCompletions(bool explicitRequest) override;

protected:
    void detach() override;
    bool wordBeforeCursorIsComplete() const override;

private:
    friend class LanguageSupport;
    explicit Bds5Language(ProgramEditor& editor);
    void charAdded(int ch);
    void completionChosen(int id, const QString& text);
    // [start, cursor) of the word being typed, in bytes; start == cursor when none.
    long wordStartBeforeCursor() const;
    QByteArray wordBeforeCursor() const;
    bool cursorInCommentOrString() const;

    Bds5Lexer* m_lexer;
    Bds5Diagnostics* m_diagnostics;
};

} // namespace editor
