// EditorActions: Motion Link's editor functions as QActions for the File, Edit and Search menus, and
// what each does on the current tab — find/replace through the find bar, go to line, blocks, merge,
// delete/undelete line, size of editor, print. The keymap decides the shortcuts menus show; the
// KeyChordFilter runs the same commands from keys typed in an editor. GUI thread only.
#pragma once

#include "editor/keymap.h"

#include <QHash>
#include <QObject>
#include <QPointer>

#include <functional>

class QAction;
class QFileDialog;
class QMenu;

namespace editor {
class EditorSizeDialog;
struct FileResult;
class FindBar;
class GoToLineDialog;
class ProgramEditor;
} // namespace editor

namespace app {

class DocumentController;
class EditorTabs;

class EditorActions final : public QObject {
    Q_OBJECT
public:
    // dialogParent: the widget dialogs belong to; its window's menu bar is what F10 opens.
    EditorActions(EditorTabs& tabs, DocumentController& documents, editor::FindBar& findBar, QWidget* dialogParent);

    // The action running command (nullptr for cursor commands, which have none).
    QAction* action(editor::EditorCommand command) const { return m_actions.value(command); }
    // Runs command on the current tab.
    void run(editor::EditorCommand command);
    // Shows keymap's keys on the actions. Editor commands' shortcuts only act while the editor area
    // has the focus (the terminal keeps ^C, ^X ... for the drive).
    void setKeymap(const editor::Keymap& keymap);

    void fillFileMenu(QMenu* menu, QMenu* recentMenu);
    void fillEditMenu(QMenu* menu);
    void fillSearchMenu(QMenu* menu);

    // The file-dialog-free halves of Save Block, Merge File and Print to PDF (the menus ask for a name).
    bool saveBlockTo(const QString& path);
    bool mergeFileFrom(const QString& path);
    bool printToPdf(const QString& path);
    // The text Undelete Line puts back ("" before the first Delete Line).
    QString deletedLine() const { return m_deletedLine; }
    // The open Size of Editor dialog (created on first use; follows the current tab).
    editor::EditorSizeDialog* showSize();
    editor::GoToLineDialog* showGoToLine();

signals:
    void statusMessage(const QString& message);

private:
    QAction* make(editor::EditorCommand command, const QString& text, std::function<void()> run);
    void addCommandActions();
    editor::ProgramEditor* current() const;
    void markBlockStart();
    void markBlockEnd();
    void copyBlock();
    void cutBlock();
    void pasteBlock();
    void saveBlock();
    void mergeFile();
    void openDialog(QFileDialog* dialog, bool (EditorActions::*take)(const QString&));
    bool report(const editor::FileResult& result, const QString& done);
    void print();
    void printPdf();
    void deleteWord();
    void deleteToEndOfLine();
    void deleteLine();
    void undeleteLine();
    void insertLine();
    void deleteEntireEditor();
    void openMenuBar();
    void showError(const QString& message);

    EditorTabs& m_tabs;
    DocumentController& m_documents;
    editor::FindBar& m_findBar;
    QWidget* m_dialogParent;
    QHash<editor::EditorCommand, QAction*> m_actions;
    QAction* m_printPdf = nullptr;
    QString m_deletedLine;
    QPointer<editor::EditorSizeDialog> m_sizeDialog;
};

} // namespace app
