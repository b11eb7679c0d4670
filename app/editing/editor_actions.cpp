// EditorActions: the actions, their menus, and the commands they run.
#include "editor_actions.h"

#include "document_controller.h"
#include "editor_tabs.h"

#include "editor/block_marker.h"
#include "editor/editor_size_dialog.h"
#include "editor/find_bar.h"
#include "editor/go_to_line_dialog.h"
#include "editor/line_commands.h"
#include "editor/program_editor.h"
#include "editor/program_printer.h"

#include <QAction>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPrintDialog>

namespace app {

using editor::EditorCommand;

EditorActions::EditorActions(EditorTabs& tabs, DocumentController& documents, editor::FindBar& findBar,
                             QWidget* dialogParent)
    : QObject(dialogParent), m_tabs(tabs), m_documents(documents), m_findBar(findBar), m_dialogParent(dialogParent) {
    addCommandActions();
    setKeymap(editor::Keymap::modern());
}

QAction* EditorActions::make(EditorCommand command, const QString& text, std::function<void()> run) {
    auto* action = new QAction(text, this);
    connect(action, &QAction::triggered, this, [run = std::move(run)] { run(); });
    m_actions.insert(command, action);
    return action;
}

void EditorActions::addCommandActions() {
    DocumentController* docs = &m_documents;
    editor::FindBar* find = &m_findBar;
    make(EditorCommand::NewFile, tr("&New"), [docs] { docs->newDocument(); });
    make(EditorCommand::OpenFile, tr("&Open..."), [docs] { docs->open(); });
    make(EditorCommand::SaveFile, tr("&Save"), [docs] { docs->save(); });
    make(EditorCommand::SaveFileAs, tr("Save &As..."), [docs] { docs->saveAs(); });
    make(EditorCommand::CloseTab, tr("&Close Tab"), [docs] { docs->closeCurrentTab(); });
    make(EditorCommand::MergeFile, tr("&Merge File..."), [this] {
        mergeFile();
    })->setStatusTip(tr("Insert a file at the cursor"));
    make(EditorCommand::Print, tr("&Print..."), [this] { print(); });
    make(EditorCommand::MenuBar, tr("Menu Bar"), [this] { openMenuBar(); });
    m_printPdf = new QAction(tr("Print to P&DF..."), this);
    connect(m_printPdf, &QAction::triggered, this, &EditorActions::printPdf);

    make(EditorCommand::Undo, tr("&Undo"), [this] {
        if (auto* e = current()) e->undo();
    });
    make(EditorCommand::Redo, tr("&Redo"), [this] {
        if (auto* e = current()) e->redo();
    });
    make(EditorCommand::MarkBlockStart, tr("Mark &Start of Block"), [this] { markBlockStart(); });
    make(EditorCommand::MarkBlockEnd, tr("Mark &End of Block"), [this] { markBlockEnd(); });
    make(EditorCommand::CopyBlock, tr("&Copy Block"), [this] { copyBlock(); });
    make(EditorCommand::CutBlock, tr("Cu&t Block"), [this] { cutBlock(); });
    make(EditorCommand::PasteBlock, tr("&Paste Block"), [this] { pasteBlock(); });
    make(EditorCommand::SaveBlock, tr("Save &Block..."), [this] {
        saveBlock();
    })->setStatusTip(tr("Write the marked block (the selection) to a file"));

    make(EditorCommand::Find, tr("&Find..."), [find] { find->showFind(); });
    make(EditorCommand::FindNext, tr("Repeat &Last Find"), [this, find] {
        if (find->searchText().isEmpty())
            find->showFind();
        else
            find->findNext();
    });
    make(EditorCommand::FindPrevious, tr("Find &Previous"), [this, find] {
        if (find->searchText().isEmpty())
            find->showFind();
        else
            find->findPrevious();
    });
    make(EditorCommand::Replace, tr("&Replace..."), [find] { find->showReplace(); });
    make(EditorCommand::GoToLine, tr("&Go to Line..."), [this] { showGoToLine(); });
    make(EditorCommand::ShowSize, tr("Size of &Editor..."), [this] { showSize(); });

    make(EditorCommand::DeleteWord, tr("Delete &Word"), [this] { deleteWord(); });
    make(EditorCommand::DeleteToEndOfLine, tr("Delete to End &of Line"), [this] { deleteToEndOfLine(); });
    make(EditorCommand::DeleteLine, tr("&Delete Line"), [this] { deleteLine(); });
    make(EditorCommand::UndeleteLine, tr("U&ndelete Line"), [this] { undeleteLine(); });
    make(EditorCommand::InsertLine, tr("&Insert New Line"), [this] { insertLine(); });
    make(EditorCommand::DeleteEntireEditor, tr("Delete Entire Editor"), [this] { deleteEntireEditor(); });

    // Editor commands act in the editor area only; file commands anywhere in the window.
    for (auto it = m_actions.cbegin(); it != m_actions.cend(); ++it) {
        const bool fileCommand = it.key() <= EditorCommand::Print;
        it.value()->setShortcutContext(fileCommand ? Qt::WindowShortcut : Qt::WidgetWithChildrenShortcut);
        if (!fileCommand) m_dialogParent->addAction(it.value());
    }
}

void EditorActions::run(EditorCommand command) {
    if (QAction* a = action(command)) a->trigger();
}

void EditorActions::setKeymap(const editor::Keymap& keymap) {
    for (auto it = m_actions.cbegin(); it != m_actions.cend(); ++it) it.value()->setShortcuts(keymap.keysFor(it.key()));
}

void EditorActions::fillFileMenu(QMenu* menu, QMenu* recentMenu) {
    using C = EditorCommand;
    menu->addAction(action(C::NewFile));
    menu->addAction(action(C::OpenFile));
    menu->addMenu(recentMenu);
    menu->addAction(action(C::SaveFile));
    menu->addAction(action(C::SaveFileAs));
    menu->addAction(action(C::CloseTab));
    menu->addSeparator();
    menu->addAction(action(C::MergeFile));
    menu->addSeparator();
    menu->addAction(action(C::Print));
    menu->addAction(m_printPdf);
}

void EditorActions::fillEditMenu(QMenu* menu) {
    using C = EditorCommand;
    for (C command : {C::Undo, C::Redo}) menu->addAction(action(command));
    menu->addSeparator();
    for (C command : {C::MarkBlockStart, C::MarkBlockEnd, C::CopyBlock, C::CutBlock, C::PasteBlock, C::SaveBlock})
        menu->addAction(action(command));
    menu->addSeparator();
    for (C command :
         {C::DeleteWord, C::DeleteToEndOfLine, C::DeleteLine, C::UndeleteLine, C::InsertLine, C::DeleteEntireEditor})
        menu->addAction(action(command));
}

void EditorActions::fillSearchMenu(QMenu* menu) {
    using C = EditorCommand;
    for (C command : {C::Find, C::FindNext, C::FindPrevious, C::Replace}) menu->addAction(action(command));
    menu->addSeparator();
    menu->addAction(action(C::GoToLine));
    menu->addAction(action(C::ShowSize));
}

editor::ProgramEditor* EditorActions::current() const {
    return m_tabs.currentEditor();
}

void EditorActions::markBlockStart() {
    auto* e = current();
    if (!e) return;
    editor::BlockMarker& marker = editor::BlockMarker::of(*e);
    // Motion Link marks "the top and the bottom" with the same key: a second ^K^B elsewhere ends the block.
    const long caret = e->SendScintilla(QsciScintilla::SCI_GETCURRENTPOS);
    if (marker.hasStart() && !e->hasSelectedText() && marker.startPosition() != caret) {
        markBlockEnd();
        return;
    }
    marker.markStart();
    int line = 0;
    int index = 0;
    e->getCursorPosition(&line, &index);
    emit statusMessage(tr("Block start marked at line %1: move to its end and mark the end").arg(line + 1));
}

void EditorActions::markBlockEnd() {
    auto* e = current();
    if (!e) return;
    if (!editor::BlockMarker::of(*e).markEnd()) {
        emit statusMessage(tr("Mark the start of the block first"));
        return;
    }
    emit statusMessage(tr("Block marked: %n character(s)", nullptr, int(e->selectedText().size())));
}

void EditorActions::copyBlock() {
    if (auto* e = current()) e->copy();
}

void EditorActions::cutBlock() {
    if (auto* e = current()) e->cut();
}

void EditorActions::pasteBlock() {
    if (auto* e = current()) e->paste();
}

void EditorActions::saveBlock() {
    auto* e = current();
    if (!e) return;
    if (!e->hasSelectedText()) {
        emit statusMessage(tr("No block is marked: select text (or mark its start and end) first"));
        return;
    }
    auto* dialog = new QFileDialog(m_dialogParent, tr("Save Block As"), m_documents.startDirectory(),
                                   saveFilter(m_tabs.fileType(e)));
    dialog->setAcceptMode(QFileDialog::AcceptSave);
    dialog->setDefaultSuffix(defaultSuffix(m_tabs.fileType(e)));
    openDialog(dialog, &EditorActions::saveBlockTo);
}

bool EditorActions::saveBlockTo(const QString& path) {
    auto* e = current();
    if (!e) return false;
    const auto result = e->saveSelectedText(path);
    if (result.ok) m_documents.rememberDirectory(path);
    return report(result, tr("Block saved to %1").arg(QDir::toNativeSeparators(path)));
}

void EditorActions::mergeFile() {
    auto* dialog = new QFileDialog(m_dialogParent, tr("Merge File"), m_documents.startDirectory(), openFilter());
    dialog->setAcceptMode(QFileDialog::AcceptOpen);
    dialog->setFileMode(QFileDialog::ExistingFile);
    openDialog(dialog, &EditorActions::mergeFileFrom);
}

bool EditorActions::mergeFileFrom(const QString& path) {
    auto* e = current();
    if (!e) return false;
    return report(e->insertFile(path), tr("Merged %1 at the cursor").arg(QFileInfo(path).fileName()));
}

// Non-modal: the dialog deletes itself when it closes and hands the chosen file to take.
void EditorActions::openDialog(QFileDialog* dialog, bool (EditorActions::*take)(const QString&)) {
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QFileDialog::fileSelected, this, take);
    dialog->open();
}

// A block file operation's outcome: its error in a message box, or done in the status bar.
bool EditorActions::report(const editor::FileResult& result, const QString& done) {
    if (!result.ok) {
        showError(result.message);
        return false;
    }
    emit statusMessage(done);
    return true;
}

void EditorActions::print() {
    auto* e = current();
    if (!e) return;
    auto* printer = new editor::ProgramPrinter(m_tabs.displayName(e));
    auto* dialog = new QPrintDialog(printer, m_dialogParent);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QObject::destroyed, this, [printer] { delete printer; });
    QPointer<editor::ProgramEditor> guarded = e;
    connect(dialog, &QDialog::accepted, this, [this, printer, guarded] {
        if (guarded && printer->printEditor(*guarded))
            emit statusMessage(tr("Printed %1").arg(m_tabs.displayName(guarded)));
    });
    dialog->open();
}

void EditorActions::printPdf() {
    auto* e = current();
    if (!e) return;
    const QString name = QFileInfo(m_tabs.displayName(e)).completeBaseName() + QStringLiteral(".pdf");
    auto* dialog = new QFileDialog(m_dialogParent, tr("Print to PDF"),
                                   QDir(m_documents.startDirectory()).filePath(name), tr("PDF files (*.pdf)"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setAcceptMode(QFileDialog::AcceptSave);
    dialog->setDefaultSuffix(QStringLiteral("pdf"));
    connect(dialog, &QFileDialog::fileSelected, this, &EditorActions::printToPdf);
    dialog->open();
}

bool EditorActions::printToPdf(const QString& path) {
    auto* e = current();
    if (!e) return false;
    if (const auto result = editor::printToPdf(*e, m_tabs.displayName(e), path); !result.ok) {
        showError(result.message);
        return false;
    }
    emit statusMessage(tr("Printed to %1").arg(QDir::toNativeSeparators(path)));
    return true;
}

void EditorActions::deleteWord() {
    if (auto* e = current()) editor::deleteWord(*e);
}

void EditorActions::deleteToEndOfLine() {
    if (auto* e = current()) editor::deleteToEndOfLine(*e);
}

void EditorActions::deleteLine() {
    if (auto* e = current()) m_deletedLine = editor::deleteLine(*e);
}

void EditorActions::undeleteLine() {
    auto* e = current();
    if (!e) return;
    if (m_deletedLine.isNull()) {
        emit statusMessage(tr("No line has been deleted yet"));
        return;
    }
    editor::undeleteLine(*e, m_deletedLine);
}

void EditorActions::insertLine() {
    if (auto* e = current()) editor::insertNewLine(*e);
}

void EditorActions::deleteEntireEditor() {
    if (auto* e = current()) {
        editor::deleteEntireEditor(*e);
        emit statusMessage(tr("Editor cleared \u2014 Undo brings the text back"));
    }
}

editor::EditorSizeDialog* EditorActions::showSize() {
    if (!m_sizeDialog) {
        m_sizeDialog = new editor::EditorSizeDialog(m_dialogParent);
        m_sizeDialog->setAttribute(Qt::WA_DeleteOnClose);
        connect(&m_tabs, &EditorTabs::currentEditorChanged, m_sizeDialog,
                [this](editor::ProgramEditor* e) { m_sizeDialog->setEditor(e, m_tabs.displayName(e)); });
    }
    m_sizeDialog->setEditor(current(), m_tabs.displayName(current()));
    m_sizeDialog->show();
    m_sizeDialog->raise();
    return m_sizeDialog;
}

editor::GoToLineDialog* EditorActions::showGoToLine() {
    auto* e = current();
    if (!e) return nullptr;
    auto* dialog = new editor::GoToLineDialog(*e, m_dialogParent);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->open();
    return dialog;
}

void EditorActions::openMenuBar() {
    auto* window = qobject_cast<QMainWindow*>(m_dialogParent->window());
    if (!window || window->menuBar()->actions().isEmpty()) return;
    window->menuBar()->setActiveAction(window->menuBar()->actions().constFirst());
}

void EditorActions::showError(const QString& message) {
    auto* box = new QMessageBox(QMessageBox::Critical, tr("ServoDesk"), message, QMessageBox::Ok, m_dialogParent);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

} // namespace app
