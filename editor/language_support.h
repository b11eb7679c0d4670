// LanguageSupport: what every drive language adds to a ProgramEditor, written once — F1 help in a popup at
// the cursor, Ctrl+Space completion, and the event filter that lets both win over application shortcuts
// while the editor has focus. A language (Bds5Language, ServoBasicLanguage, MplLanguage) supplies its help
// as data and, when it completes names, its completion list. Owned by the editor; GUI thread only.
#pragma once

#include "outline.h"
#include "program_editor.h"

#include <QObject>
#include <QString>

namespace editor {

class HelpPopup;

class LanguageSupport : public QObject {
    Q_OBJECT
public:
    // A language's F1 help: pure functions over its catalog (editor/<family>_help.h).
    struct Help {
        QString (*topicAt)(const QString& line, int column) = nullptr; // the topic at a 0-based column
        QString (*html)(const QString& topic) = nullptr;               // empty: the catalog has no such topic
        QString unknownTopic;        // the popup for a topic the catalog lacks; %1 is the topic, HTML-escaped
        bool opensReference = false; // a known topic also goes out as ProgramEditor::helpRequested
    };

    // A language's outline (the Outline dock, Go to label): how it finds its labels and entry points, and
    // what the dock says when a program has none ("No routines (@ lines) in this program yet").
    struct Outlining {
        OutlineOf of = nullptr;
        QString none;
    };

    // The language installed in editor (whichever it is), or nullptr for plain text.
    static LanguageSupport* of(const QsciScintilla* editor) { return find<LanguageSupport>(editor); }

    HelpPopup* helpPopup() const { return m_help; }
    Outline outline(const QString& programText) const { return m_outline.of(programText); }
    const QString& noOutline() const { return m_outline.none; }

    // The help topic under (or just before) the cursor; empty when none.
    QString topicAtCursor() const;
    // F1: shows the topic's help under the cursor. Returns the topic (empty: nothing to explain, nothing shown).
    QString showHelpAtCursor();
    void hideHelp();
    // Shows the completion list for the word before the cursor (explicit: Ctrl+Space, even for fewer than
    // two letters). False when nothing matches or the language completes nothing.
    virtual bool showCompletions(bool explicitRequest);

protected:
    // completes: the language has a completion list, so Ctrl+Space is the editor's.
    LanguageSupport(ProgramEditor& editor, Help help, Outlining outline, bool completes);

    // The support of type L installed in editor, or nullptr.
    template <class L> static L* find(const QsciScintilla* editor) {
        return editor ? editor->findChild<L*>(QString(), Qt::FindDirectChildrenOnly) : nullptr;
    }
    // Installs L once (later calls return the same object); L makes LanguageSupport a friend.
    template <class L> static L* installIn(ProgramEditor& editor) {
        if (L* existing = find<L>(&editor)) return existing;
        return new L(editor);
    }
    // Detaches and deletes the L installed in editor, if any.
    template <class L> static void uninstallFrom(ProgramEditor& editor) {
        if (L* language = find<L>(&editor)) {
            language->detach();
            delete language;
        }
    }
    // Undoes what the constructor did to the editor (popup, key handling); a language adds its own (folding,
    // annotations, lexer). Not in the destructor: the editor may be half destroyed by then.
    virtual void detach();
    // Enter while the completion list is open: true when the word before the cursor already names something
    // (a new line, not a pick from the list).
    virtual bool wordBeforeCursorIsComplete() const { return false; }

    bool eventFilter(QObject* watched, QEvent* event) override;

    ProgramEditor& m_editor;

private:
    Help m_source;
    Outlining m_outline;
    bool m_completes;
    HelpPopup* m_help;
    long m_helpPosition = -1; // where the cursor was when the help opened
};

} // namespace editor
