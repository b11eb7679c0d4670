// EditorTabs: one tab per open file, each a ProgramEditor with its own path, modified state and undo
// history. The tab shows the file type's icon, the name and "*" while modified. Every editor is created
// here, so per-editor features hook in once through editorCreated(). GUI thread only.
#pragma once

#include "file_types.h"

#include <QList>
#include <QTabWidget>

namespace editor {
class ProgramEditor;
}

namespace app {

class EditorTabs final : public QTabWidget {
    Q_OBJECT
public:
    explicit EditorTabs(QWidget* parent = nullptr);

    // Adds an empty editor named untitledName (until it has a file) and makes it the current tab.
    editor::ProgramEditor* addEditor(const QString& untitledName);
    // Closes the tab and deletes its editor at once (no questions: ask DocumentController first).
    void removeEditor(editor::ProgramEditor* editor);

    // Never null after the first addEditor().
    editor::ProgramEditor* currentEditor() const;
    editor::ProgramEditor* editorAt(int index) const;
    QList<editor::ProgramEditor*> editors() const;
    // The tab holding the file at path (compared as canonical paths), or -1.
    int indexOfFile(const QString& path) const;

    // The file's name, or the untitled name ("untitled.bds", "hello.bds").
    QString displayName(const editor::ProgramEditor* editor) const;
    void setUntitledName(editor::ProgramEditor* editor, const QString& name);
    // A name no other tab uses: "untitled.bds", "untitled-2.bds", ...
    QString freeUntitledName(FileType type) const;
    FileType fileType(const editor::ProgramEditor* editor) const;

    // Updates the tab's text, icon, tool tip and lexer after the editor's file changed (open, save as).
    void refreshTab(editor::ProgramEditor* editor);

signals:
    void currentEditorChanged(editor::ProgramEditor* editor);
    void editorCreated(editor::ProgramEditor* editor);
    // The current tab's name or modified state changed (for the window title).
    void currentDocumentChanged();

private:
    void applyLexer(editor::ProgramEditor* editor, FileType type);
};

} // namespace app
