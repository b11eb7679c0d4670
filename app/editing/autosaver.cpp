// Autosaver: change tracking and timed writes.
#include "autosaver.h"

#include "editor_tabs.h"
#include "recovery_store.h"

#include "editor/program_editor.h"

#include <QUuid>

namespace app {

namespace {
const char* const kIdProperty = "servodeskRecoveryId";
} // namespace

Autosaver::Autosaver(EditorTabs& tabs, RecoveryStore& store, QObject* parent)
    : QObject(parent), m_tabs(tabs), m_store(store) {
    m_timer.setSingleShot(true);
    m_timer.setInterval(kDelayMs);
    connect(&m_timer, &QTimer::timeout, this, &Autosaver::flush);
    connect(&tabs, &EditorTabs::editorCreated, this, &Autosaver::watch);
    for (auto* editor : tabs.editors()) watch(editor);
}

Autosaver::~Autosaver() {
    m_store.removeSession();
}

void Autosaver::watch(editor::ProgramEditor* editor) {
    editor->setProperty(kIdProperty, QUuid::createUuid().toString(QUuid::WithoutBraces));
    const QString id = idOf(editor);
    connect(editor, &QsciScintilla::textChanged, this, [this, editor] { changed(editor); });
    connect(editor, &QsciScintilla::modificationChanged, this, [this, editor, id](bool modified) {
        if (modified) return;
        m_dirty.remove(editor); // saved, or undone back to the saved text: nothing to recover
        m_store.remove(id);
    });
    connect(editor, &QObject::destroyed, this, [this, editor, id] {
        m_dirty.remove(editor);
        m_store.remove(id);
    });
}

void Autosaver::flush() {
    m_timer.stop();
    int written = 0;
    const auto dirty = m_dirty;
    m_dirty.clear();
    for (auto* editor : dirty) {
        if (!editor->isModified()) {
            m_store.remove(idOf(editor));
            continue;
        }
        if (m_store.write(idOf(editor), editor->filePath(), m_tabs.displayName(editor), editor->text()))
            ++written;
        else
            m_dirty.insert(editor); // try again with the next change
    }
    if (written > 0) emit buffersWritten(written);
}

void Autosaver::changed(editor::ProgramEditor* editor) {
    m_dirty.insert(editor);
    if (!m_timer.isActive()) m_timer.start(); // not restarted: a write at most kDelayMs after a change
}

QString Autosaver::idOf(const editor::ProgramEditor* editor) const {
    return editor->property(kIdProperty).toString();
}

} // namespace app
