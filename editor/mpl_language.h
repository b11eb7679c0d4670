// MplLanguage: what makes a ProgramEditor an MPL (PMC-960) editor, owned by that editor — the MPL lexer
// (character-class colours, one fold per @label routine), the program check as annotations (unknown
// characters, undefined labels, a buffer over 1,940 bytes) and F1 help from the catalog in a popup.
// No completion: MPL commands are one to three letters. Installed by EditorTabs for every .mpl tab.
// GUI thread only.
#pragma once

#include "language_support.h"

#include <QTimer>

namespace editor {

class MplLexer;

class MplLanguage final : public LanguageSupport {
    Q_OBJECT
public:
    static constexpr int kFoldMargin = 2;
    static constexpr int kCheckDelayMs = 300; // after the last keystroke

    // Installs MPL support in editor (once; later calls return the same object).
    static MplLanguage* install(ProgramEditor& editor) { return installIn<MplLanguage>(editor); }
    // The support installed in editor, or nullptr.
    static MplLanguage* of(const QsciScintilla* editor) { return find<MplLanguage>(editor); }
    // Takes it out again; the lexer stays with the editor, which may replace it.
    static void uninstall(ProgramEditor& editor) { uninstallFrom<MplLanguage>(editor); }

    MplLexer* lexer() const { return m_lexer; }

    // Runs the program check now and shows its findings as annotations; returns how many there are.
    int checkNow();

protected:
    void detach() override;

private:
    friend class LanguageSupport;
    explicit MplLanguage(ProgramEditor& editor);

    MplLexer* m_lexer;
    QTimer m_check;
};

} // namespace editor
