// DocumentController: the File menu's work on the editor tabs — new, open (with recent files), save,
// save as, close tab, and asking about unsaved edits, per tab. All dialogs are opened non-blocking
// (open(), never exec()); results arrive later. GUI thread only.
#pragma once

#include "file_types.h"

#include <QList>
#include <QObject>
#include <QPointer>
#include <QString>

#include <functional>

namespace editor {
class ProgramEditor;
}

namespace app {

class EditorTabs;
class RecentFiles;

class DocumentController final : public QObject {
    Q_OBJECT
public:
    static inline const QString kLastDirKey = QStringLiteral("files/lastDir");

    // dialogParent: the window the file and question dialogs belong to.
    DocumentController(EditorTabs& tabs, RecentFiles& recent, QWidget* dialogParent);

    // Opens a read-only file (such as a resource) in a new tab as an unnamed document called displayName.
    void openTemplate(const QString& path, const QString& displayName);
    // A new, empty tab ("untitled.bds", "untitled-2.bds", ...).
    void newDocument();
    // Asks for files (several may be chosen) and opens each in its own tab.
    void open();
    // Opens path in a new tab, or shows its tab when it is open already. False (and an error shown)
    // when it cannot be read.
    bool openFile(const QString& path);
    // Save / Save As of the current tab.
    void save();
    void saveAs();
    // Closes a tab after asking about its unsaved edits. Closing the last tab leaves a new empty one.
    // chosen: the window always has an editor, so "the current editor" is never null.
    void closeTab(int index);
    void closeCurrentTab();

    // Calls proceed once the current tab's unsaved edits are saved or discarded; never if the user cancels.
    void whenSafeToDiscard(std::function<void()> proceed);
    void whenSafeToDiscard(editor::ProgramEditor* editor, std::function<void()> proceed);
    // The same for every tab, asking about each modified tab in turn (for quitting).
    void whenAllSafeToDiscard(std::function<void()> proceed);
    bool hasUnsavedChanges() const;

    // The current tab's "hello.bds", "untitled.bds" or file name.
    QString displayName() const;
    // Where file dialogs start: the current file's folder, else the last folder used, else home.
    QString startDirectory() const;
    void rememberDirectory(const QString& path);

signals:
    void documentChanged(); // a different document (or name) is in the current tab
    void statusMessage(const QString& message);
    void fileSaved(editor::ProgramEditor* editor, const QString& path);
    void fileLoaded(editor::ProgramEditor* editor, const QString& path); // opened from disk into a new tab
    // File > Open (or Open Recent) named a file already open in editor; its tab is current now.
    void fileOpenedAgain(editor::ProgramEditor* editor);

private:
    void askEach(QList<QPointer<editor::ProgramEditor>> remaining, std::function<void()> proceed);
    void saveThen(editor::ProgramEditor* editor, std::function<void()> then);
    void saveAsThen(editor::ProgramEditor* editor, std::function<void()> then);
    bool writeTo(editor::ProgramEditor* editor, const QString& path);
    using FileSignal = void (DocumentController::*)(editor::ProgramEditor*, const QString&);
    void tabNowShows(editor::ProgramEditor* editor, const QString& path, FileSignal done, const QString& status);
    void showError(const QString& message);

    EditorTabs& m_tabs;
    RecentFiles& m_recent;
    QWidget* m_dialogParent;
};

} // namespace app
