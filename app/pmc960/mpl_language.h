// MplLanguage: what makes a ProgramEditor an MPL (PMC-960) editor, owned by that editor — the MPL lexer
// (character-class colours, one fold per @label routine), the program check as annotations (unknown
// characters, undefined labels, a buffer over 1,940 bytes) and F1 help from the catalog in a popup.
// Installed by EditorTabs for every .mpl tab. GUI thread only.
#pragma once

#include <QObject>
#include <QTimer>

class QsciScintilla;

namespace editor {
class HelpPopup;
class MplLexer;
class ProgramEditor;
} // namespace editor

namespace app {

class MplLanguage final : public QObject {
    Q_OBJECT
public:
    static constexpr int kFoldMargin = 2;
    static constexpr int kCheckDelayMs = 300; // after the last keystroke

    // Installs MPL support in editor (once; later calls return the same object).
    static MplLanguage* install(editor::ProgramEditor& editor);
    static MplLanguage* of(const QsciScintilla* editor);
    // Takes it out again; the lexer stays with the editor, which may replace it.
    static void uninstall(editor::ProgramEditor& editor);

    editor::MplLexer* lexer() const { return m_lexer; }
    editor::HelpPopup* helpPopup() const { return m_help; }

    // The catalog topic under the cursor ("A", "TGP", "#B6", "@"), empty when none.
    QString topicAtCursor() const;
    // F1: shows the topic's help under the cursor; returns it (empty: nothing shown).
    QString showHelpAtCursor();
    void hideHelp();
    // Runs the program check now and shows its findings as annotations; returns how many there are.
    int checkNow();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    explicit MplLanguage(editor::ProgramEditor& editor);

    editor::ProgramEditor& m_editor;
    editor::MplLexer* m_lexer;
    editor::HelpPopup* m_help;
    QTimer m_check;
    long m_helpPosition = -1;
};

} // namespace app
