// Autosaver: nothing typed is lost. kDelayMs after a change (at the latest, even while typing goes on)
// every modified tab's text is written to the RecoveryStore with its original path; a clean save, undoing
// back to the saved text, or closing the tab removes its recovery file; a clean exit removes the whole
// session. GUI thread only.
#pragma once

#include <QHash>
#include <QObject>
#include <QPointer>
#include <QSet>
#include <QTimer>

namespace editor {
class ProgramEditor;
}

namespace app {

class EditorTabs;
class RecoveryStore;

class Autosaver final : public QObject {
    Q_OBJECT
public:
    static constexpr int kDelayMs = 3000;

    Autosaver(EditorTabs& tabs, RecoveryStore& store, QObject* parent = nullptr);
    // A clean exit: the session's recovery files go.
    ~Autosaver() override;

    // Follows editor's changes from now on (EditorTabs::editorCreated is connected already).
    void watch(editor::ProgramEditor* editor);
    // Writes every changed buffer now.
    void flush();

signals:
    // After each write, with the number of buffers written (for tests and the status bar).
    void buffersWritten(int count);

private:
    void changed(editor::ProgramEditor* editor);
    QString idOf(const editor::ProgramEditor* editor) const;

    EditorTabs& m_tabs;
    RecoveryStore& m_store;
    QSet<editor::ProgramEditor*> m_dirty;
    QTimer m_timer;
};

} // namespace app
