// DiskWatcher: keeps the editor tabs true to their files on disk. Every file open in a tab is watched, and
// its folder too, so a file another editor replaces (writes a new file and renames it over the old one)
// is still seen. kSettleMs after the last change the file's content is compared with what ServoDesk last
// read or wrote there (a SHA-1 of the bytes), so our own saves, and touches that change nothing, say
// nothing. Then a tab without unsaved edits reloads and the status bar says so; a tab with edits keeps
// them, and the DiskChangeBar asks: Reload, or Keep My Edits. A file that cannot be shown any more (binary,
// oversized, unreadable) is never loaded in part: the tab keeps its text and the bar says why.
// GUI thread only.
#pragma once

#include <QByteArray>
#include <QFileSystemWatcher>
#include <QHash>
#include <QList>
#include <QObject>
#include <QPointer>
#include <QSet>
#include <QString>
#include <QTimer>

namespace editor {
class ProgramEditor;
}

namespace app {

class DiskChangeBar;
class EditorTabs;

class DiskWatcher final : public QObject {
    Q_OBJECT
public:
    // What a look at the disk found, and did.
    enum class Outcome {
        Unchanged, // the file holds what the tab was loaded from or saved as
        Reloaded,  // it changed; the tab had no edits and now shows the new file
        Asked,     // the bar asks about it (the tab has edits, or the new file cannot be shown)
        Removed,   // the file is gone; the tab keeps its text
    };
    Q_ENUM(Outcome)

    // Editors write a file in several steps (truncate, write; or write elsewhere, rename): look once they
    // are done.
    static constexpr int kSettleMs = 150;

    DiskWatcher(EditorTabs& tabs, DiskChangeBar& bar, QObject* parent = nullptr);

    // The editor's file was just read or written by ServoDesk (open, save, save as): from now on its
    // content on disk is the editor's, and changes to it are watched. An editor without a file is not.
    void track(editor::ProgramEditor* editor);
    // File > Open of a file already open in editor: show the disk's content, or ask when the tab has edits.
    void reopened(editor::ProgramEditor* editor);

    // The bar's answers for the editor it asks about (the current tab's question first).
    void reload(editor::ProgramEditor* editor);
    void keepEdits(editor::ProgramEditor* editor);
    // Whether the bar has a question about editor's file.
    bool isAsking(const editor::ProgramEditor* editor) const;

signals:
    void statusMessage(const QString& message);
    // After every look at a file on disk, with what it found (tests wait for this, not for time).
    void examined(const QString& path, app::DiskWatcher::Outcome outcome);

private:
    struct Entry {
        QString path;
        QByteArray digest; // of the bytes ServoDesk last read, wrote or asked about; empty when missing
        bool exists = true;
    };
    struct Question {
        QPointer<editor::ProgramEditor> editor;
        QString html;
        QString keepText;
    };

    void pathChanged(const QString& path);
    void directoryChanged(const QString& directory);
    void settle();
    Outcome examine(editor::ProgramEditor* editor);
    // chosen: whether the user asked for it (the bar's Reload) rather than the disk changing under a clean tab.
    Outcome reloadNow(editor::ProgramEditor* editor, bool chosen = false);
    void ask(editor::ProgramEditor* editor, const QString& html, const QString& keepText);
    void forgetQuestion(const editor::ProgramEditor* editor);
    void showQuestion();
    void forget(editor::ProgramEditor* editor);
    void watchPath(const QString& path);
    void unwatchUnused(const QString& path);
    QString nameOf(const editor::ProgramEditor* editor) const;
    static QByteArray digestOf(const QString& path);

    EditorTabs& m_tabs;
    DiskChangeBar& m_bar;
    QFileSystemWatcher m_watcher;
    QHash<editor::ProgramEditor*, Entry> m_entries;
    QList<Question> m_questions;             // oldest first
    QPointer<editor::ProgramEditor> m_shown; // whose question the bar shows
    QSet<QString> m_changed;                 // paths to look at when m_settle fires
    QTimer m_settle;
};

} // namespace app
