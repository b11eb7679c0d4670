// Bds5Language: everything that makes a ProgramEditor a BDS5 editor, owned by that editor — the lexer
// (colours, folding), diagnostics as you type, completion (after two letters, or Ctrl+Space) and F1 help
// (a popup, plus ProgramEditor::helpRequested). Install once per editor (every tab). GUI thread only.
#pragma once

#include "bds5_lexer.h"

#include <QObject>

class QsciScintilla;

namespace editor {

class Bds5Diagnostics;
class HelpPopup;
class ProgramEditor;

class Bds5Language final : public QObject {
    Q_OBJECT
public:
    static constexpr int kFoldMargin = 2;
    static constexpr int kCompletionListId = 51; // showUserList id
    static constexpr int kCompletionMinLetters = 2;

    // Installs BDS5 support in editor (once; later calls return the same object).
    static Bds5Language* install(ProgramEditor& editor);
    // The support installed in editor, or nullptr.
    static Bds5Language* of(const QsciScintilla* editor);
    // Takes it out again (the file became a capture, say): diagnostics, folding, popup and key handling
    // go; the lexer stays with the editor, which may replace it. Nothing happens when none is installed.
    static void uninstall(ProgramEditor& editor);

    Bds5Lexer* lexer() const { return m_lexer; }
    Bds5Diagnostics* diagnostics() const { return m_diagnostics; }
    HelpPopup* helpPopup() const { return m_help; }

    // Light or dark colours for the text, margins, annotations and popups.
    void setTheme(Bds5Lexer::Theme theme);

    // The help topic under (or just before) the cursor; empty when none.
    QString topicAtCursor() const;
    // F1: shows the topic's help under the cursor and emits the editor's helpRequested(topic).
    // Returns the topic (empty: nothing to explain, nothing shown).
    QString showHelpAtCursor();
    void hideHelp();
    // Shows the completion list for the word before the cursor (explicit: even for fewer than two
    // letters, as Ctrl+Space does). False when nothing matches.
    bool showCompletions(bool explicitRequest);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    explicit Bds5Language(ProgramEditor& editor);
    void charAdded(int ch);
    void completionChosen(int id, const QString& text);
    // [start, cursor) of the word being typed, in bytes; start == cursor when none.
    long wordStartBeforeCursor() const;
    bool cursorInCommentOrString() const;

    ProgramEditor& m_editor;
    Bds5Lexer* m_lexer;
    Bds5Diagnostics* m_diagnostics;
    HelpPopup* m_help;
    long m_helpPosition = -1; // where the cursor was when the help opened
};

} // namespace editor
