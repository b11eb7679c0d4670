// EditorArea: the IDE's centre — the crash-recovery bar, the bar asking about files changed on disk, the
// editor tabs and the find bar — with the document, recent-file, disk-watch, autosave and editor-command
// machinery behind them, and the keymap in use.
// MainWindow puts it in the middle and asks it for menus and status-bar cells. GUI thread only.
#pragma once

#include "recovery_store.h"

#include "editor/editor_size.h"

#include <QPointer>
#include <QWidget>

#include <functional>
#include <memory>

class QLabel;
class QMenu;
class QStatusBar;

namespace editor {
class FindBar;
class KeyChordFilter;
class ProgramEditor;
} // namespace editor

namespace app {

class Autosaver;
class DiskChangeBar;
class DiskWatcher;
class DocumentController;
class EditorActions;
class EditorTabs;
class RecentFiles;
class RecoveryBar;

class EditorArea final : public QWidget {
    Q_OBJECT
public:
    explicit EditorArea(QWidget* parent = nullptr);
    ~EditorArea() override;

    // The current tab's editor; never null once a document is open.
    editor::ProgramEditor* currentEditor() const;
    EditorTabs* tabs() const { return m_tabs; }
    DocumentController* documents() const { return m_documents; }
    EditorActions* actions() const { return m_actions; }
    editor::FindBar* findBar() const { return m_findBar; }
    RecoveryBar* recoveryBar() const { return m_recoveryBar; }
    // Files changed on disk by other programs: reloaded, or asked about in the bar over the tabs.
    DiskWatcher* diskWatcher() const { return m_diskWatcher; }
    DiskChangeBar* diskChangeBar() const { return m_diskBar; }
    RecentFiles* recentFiles() const { return m_recent; }
    Autosaver* autosaver() const { return m_autosaver.get(); }
    RecoveryStore& recoveryStore() const { return *m_store; }

    // The keymap in use, "modern" or "classic" (editor::Keymap::kSettingsKey in QSettings).
    QString keymapName() const;
    // Switches every editor (and the menus' shortcuts) to the keymap called name. Does not store it.
    void applyKeymap(const QString& name);
    // Applies the keymap QSettings names (after the Options dialog wrote it).
    void reloadKeymap();

    void fillFileMenu(QMenu* menu);
    void fillEditMenu(QMenu* menu);
    void fillSearchMenu(QMenu* menu);
    // Adds the cursor/size cell and the keymap cell to the status bar.
    void installStatusWidgets(QStatusBar* statusBar);

    bool hasUnsavedChanges() const;
    // Calls proceed once every tab's unsaved edits are saved or discarded; never if the user cancels.
    void whenSafeToClose(std::function<void()> proceed);

    // Opens the buffers a crashed session left in tabs (modified, with their original paths); returns
    // how many. Then forgets that session.
    int restoreRecovered();
    void discardRecovered();
    // Help > Classic Editor Keys: the classic keymap's table (resources/help), in a non-modal window.
    QWidget* showClassicKeys();
    // The size figures the status bar shows for the current tab ("Line 3 of 12 · 240 of 24,000 bytes").
    QString sizeStatusText() const;

signals:
    void currentEditorChanged(editor::ProgramEditor* editor);
    // The current tab's name or modified state changed.
    void currentDocumentChanged();
    void statusMessage(const QString& message);

private:
    void setUpEditor(editor::ProgramEditor* editor);
    void editorChanged(editor::ProgramEditor* editor);
    void measure();
    void updateSizeLabel();
    void showPendingKeys(const QString& keys);

    std::unique_ptr<RecoveryStore> m_store;
    RecoveryBar* m_recoveryBar;
    EditorTabs* m_tabs;
    editor::FindBar* m_findBar;
    RecentFiles* m_recent;
    DocumentController* m_documents;
    EditorActions* m_actions;
    editor::KeyChordFilter* m_chords;
    QMenu* m_recentMenu;
    std::unique_ptr<Autosaver> m_autosaver; // after m_store: it removes the session when destroyed
    editor::EditorSize m_size;              // of the current tab, refreshed on each edit
    DiskChangeBar* m_diskBar = nullptr;
    DiskWatcher* m_diskWatcher = nullptr; // deleted first: it follows the tabs' editors as they go
    QLabel* m_sizeLabel = nullptr;
    QLabel* m_keysLabel = nullptr;
    QMetaObject::Connection m_cursorConnection;
    QMetaObject::Connection m_textConnection;
};

} // namespace app
