// DiskWatcher: file and folder watches, the comparison with the disk, reloading and the bar's questions.
#include "disk_watcher.h"

#include "disk_change_bar.h"
#include "editor_tabs.h"

#include "editor/program_editor.h"

#include <QCryptographicHash>
#include <QDateTime>
#include <QFile>
#include <QFileInfo>

#include <utility>

namespace app {

namespace {
// Larger than any program the editor opens (it refuses them whole): such a file's size and time stand for
// its content, so a file grown huge is never read on the GUI thread just to compare it.
constexpr qint64 kMaxDigestBytes = 8 << 20;

QString lineWithoutEnd(const editor::ProgramEditor& editor, int line) {
    QString text = editor.text(line);
    while (text.endsWith(QLatin1Char('\n')) || text.endsWith(QLatin1Char('\r'))) text.chop(1);
    return text;
}
} // namespace

DiskWatcher::DiskWatcher(EditorTabs& tabs, DiskChangeBar& bar, QObject* parent)
    : QObject(parent), m_tabs(tabs), m_bar(bar) {
    m_settle.setSingleShot(true);
    m_settle.setInterval(kSettleMs);
    connect(&m_settle, &QTimer::timeout, this, &DiskWatcher::settle);
    connect(&m_watcher, &QFileSystemWatcher::fileChanged, this, &DiskWatcher::pathChanged);
    connect(&m_watcher, &QFileSystemWatcher::directoryChanged, this, &DiskWatcher::directoryChanged);
    connect(&m_tabs, &EditorTabs::currentEditorChanged, this, &DiskWatcher::showQuestion);
    connect(&m_bar, &DiskChangeBar::reloadRequested, this, [this] { reload(m_shown); });
    connect(&m_bar, &DiskChangeBar::keepRequested, this, [this] { keepEdits(m_shown); });
}

void DiskWatcher::track(editor::ProgramEditor* editor) {
    if (!editor) return;
    const bool known = m_entries.contains(editor);
    const QString old = known ? m_entries.value(editor).path : QString();
    if (isAsking(editor)) { // just read or written (saved over the change): the tab and the disk agree
        forgetQuestion(editor);
        showQuestion();
    }
    if (editor->filePath().isEmpty()) {
        m_entries.remove(editor);
        unwatchUnused(old);
        return;
    }
    Entry entry;
    entry.path = QFileInfo(editor->filePath()).absoluteFilePath();
    entry.digest = digestOf(entry.path);
    entry.exists = QFileInfo::exists(entry.path);
    m_entries.insert(editor, entry);
    if (!known) connect(editor, &QObject::destroyed, this, [this, editor] { forget(editor); });
    watchPath(entry.path);
    if (old != entry.path) unwatchUnused(old); // after Save As
}

void DiskWatcher::reopened(editor::ProgramEditor* editor) {
    if (!editor) return;
    if (!m_entries.contains(editor)) return track(editor);
    const QString path = m_entries.value(editor).path;
    if (editor->isModified()) {
        // Opening the file again asks for the disk's version; the tab's edits are not thrown away unasked.
        ask(editor,
            tr("<b>%1</b> is already open, with unsaved edits. Reload it from disk (Edit > Undo brings your edits back) "
               "or keep your edits?")
                .arg(nameOf(editor).toHtmlEscaped()),
            tr("&Keep My Edits"));
        emit examined(path, Outcome::Asked);
        return;
    }
    // A question still open (the new file could not be shown) is answered by trying again.
    const Outcome outcome = isAsking(editor) ? reloadNow(editor) : examine(editor);
    emit examined(path, outcome);
}

void DiskWatcher::reload(editor::ProgramEditor* editor) {
    if (!editor || !m_entries.contains(editor)) return;
    const Outcome outcome = reloadNow(editor, true);
    emit examined(m_entries.value(editor).path, outcome);
}

void DiskWatcher::keepEdits(editor::ProgramEditor* editor) {
    if (!editor) return;
    forgetQuestion(editor);
    showQuestion();
    emit statusMessage(editor->isModified()
                           ? tr("Kept your edits to %1: Save writes them over the file on disk").arg(nameOf(editor))
                           : tr("Kept the text of %1 as it was").arg(nameOf(editor)));
}

bool DiskWatcher::isAsking(const editor::ProgramEditor* editor) const {
    for (const Question& q : m_questions)
        if (q.editor == editor) return true;
    return false;
}

void DiskWatcher::pathChanged(const QString& path) {
    m_changed.insert(path);
    m_settle.start();
}

void DiskWatcher::directoryChanged(const QString& directory) {
    // A file created, removed or renamed in the folder: an editor's atomic save replaces the file this way,
    // and a file deleted and written again is a new file the old watch does not see.
    for (const Entry& entry : std::as_const(m_entries))
        if (QFileInfo(entry.path).absolutePath() == directory) m_changed.insert(entry.path);
    if (!m_changed.isEmpty()) m_settle.start();
}

void DiskWatcher::settle() {
    const QSet<QString> paths = std::exchange(m_changed, {});
    for (const QString& path : paths) {
        watchPath(path);
        QList<editor::ProgramEditor*> editors;
        for (auto it = m_entries.cbegin(); it != m_entries.cend(); ++it)
            if (it->path == path) editors.append(it.key());
        for (editor::ProgramEditor* editor : editors) emit examined(path, examine(editor));
    }
}

DiskWatcher::Outcome DiskWatcher::examine(editor::ProgramEditor* editor) {
    Entry& entry = m_entries[editor];
    const QString name = nameOf(editor);
    if (editor->filePath().isEmpty() || QFileInfo(editor->filePath()).absoluteFilePath() != entry.path)
        return Outcome::Unchanged; // the tab has another file (or none) now: track() follows it
    if (!QFileInfo::exists(entry.path)) {
        if (entry.exists)
            emit statusMessage(tr("%1 was removed from disk: the tab keeps its text (Save writes it again)").arg(name));
        entry.exists = false;
        return Outcome::Removed;
    }
    // The digest is kept while the file is gone: written back unchanged (deleted and created again), it
    // is the same file.
    const QByteArray digest = digestOf(entry.path);
    entry.exists = true;
    if (!digest.isEmpty() && digest == entry.digest) return Outcome::Unchanged;
    entry.digest = digest; // looked at: the same content is not reloaded or asked about again
    if (!editor->isModified()) return reloadNow(editor);
    ask(editor,
        tr("<b>%1</b> changed on disk, and this tab has unsaved edits. Reload it (Edit > Undo brings your edits back) or "
           "keep your edits (Save writes them over the file)?")
            .arg(name.toHtmlEscaped()),
        tr("&Keep My Edits"));
    emit statusMessage(tr("%1 changed on disk: your edits stay until you choose Reload or Keep My Edits").arg(name));
    return Outcome::Asked;
}

DiskWatcher::Outcome DiskWatcher::reloadNow(editor::ProgramEditor* editor, bool chosen) {
    Entry& entry = m_entries[editor];
    const QString name = nameOf(editor);
    int line = 0;
    int index = 0;
    editor->getCursorPosition(&line, &index);
    const int top = editor->firstVisibleLine();
    // loadFile refuses a binary or oversized file whole and leaves the tab as it was (issue 19, item 7).
    if (const editor::FileResult result = editor->reloadFile(entry.path); !result.ok) {
        ask(editor,
            tr("<b>%1</b> changed on disk, but the tab cannot show the new file: %2 The tab keeps the text it had.")
                .arg(name.toHtmlEscaped(), result.message.toHtmlEscaped()),
            editor->isModified() ? tr("&Keep My Edits") : tr("&Keep This Text"));
        emit statusMessage(tr("%1 changed on disk and was not reloaded: %2").arg(name, result.message));
        return Outcome::Asked;
    }
    entry.digest = digestOf(entry.path);
    entry.exists = true;
    // The user keeps their place in the file.
    const int at = qBound(0, line, qMax(0, editor->lines() - 1));
    editor->setCursorPosition(at, qMin(index, int(lineWithoutEnd(*editor, at).size())));
    editor->setFirstVisibleLine(top);
    forgetQuestion(editor);
    showQuestion();
    emit statusMessage(chosen ? tr("Reloaded %1 from disk").arg(name) : tr("Reloaded %1: changed on disk").arg(name));
    return Outcome::Reloaded;
}

void DiskWatcher::ask(editor::ProgramEditor* editor, const QString& html, const QString& keepText) {
    forgetQuestion(editor);
    m_questions.append({editor, html, keepText});
    showQuestion();
}

void DiskWatcher::forgetQuestion(const editor::ProgramEditor* editor) {
    m_questions.removeIf([editor](const Question& q) { return !q.editor || q.editor == editor; });
}

// The bar asks about the current tab's file when it has a question, else about the oldest question.
void DiskWatcher::showQuestion() {
    m_questions.removeIf([](const Question& q) { return !q.editor; });
    if (m_questions.isEmpty()) {
        m_shown = nullptr;
        m_bar.hide();
        return;
    }
    const Question* shown = &m_questions.constFirst();
    for (const Question& q : std::as_const(m_questions))
        if (q.editor == m_tabs.currentEditor()) shown = &q;
    m_shown = shown->editor;
    QString html = shown->html;
    if (const qsizetype more = m_questions.size() - 1; more > 0)
        html += more == 1 ? tr(" One more open file changed on disk.")
                          : tr(" %1 more open files changed on disk.").arg(more);
    m_bar.ask(html, shown->keepText);
}

void DiskWatcher::forget(editor::ProgramEditor* editor) {
    // From QObject::destroyed: editor is only a key now.
    const QString path = m_entries.take(editor).path;
    unwatchUnused(path);
    if (m_questions.isEmpty()) return;
    showQuestion(); // drops the closed tab's question
}

void DiskWatcher::watchPath(const QString& path) {
    // Added again each time: a file replaced by a rename is another file, and the old watch followed the old.
    if (m_watcher.files().contains(path)) m_watcher.removePath(path);
    if (QFileInfo::exists(path) && !m_watcher.addPath(path))
        emit statusMessage(tr("Cannot watch %1: changes other programs make to it will not be noticed")
                               .arg(QFileInfo(path).fileName()));
    const QString directory = QFileInfo(path).absolutePath();
    if (!m_watcher.directories().contains(directory)) m_watcher.addPath(directory);
}

void DiskWatcher::unwatchUnused(const QString& path) {
    if (path.isEmpty()) return;
    const QString directory = QFileInfo(path).absolutePath();
    bool fileUsed = false;
    bool directoryUsed = false;
    for (const Entry& entry : std::as_const(m_entries)) {
        fileUsed = fileUsed || entry.path == path;
        directoryUsed = directoryUsed || QFileInfo(entry.path).absolutePath() == directory;
    }
    if (!fileUsed && m_watcher.files().contains(path)) m_watcher.removePath(path);
    if (!directoryUsed && m_watcher.directories().contains(directory)) m_watcher.removePath(directory);
}

QString DiskWatcher::nameOf(const editor::ProgramEditor* editor) const {
    return m_tabs.displayName(editor);
}

QByteArray DiskWatcher::digestOf(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return {};
    if (file.size() > kMaxDigestBytes)
        return "size " + QByteArray::number(file.size()) + " time " +
               QByteArray::number(QFileInfo(path).lastModified().toMSecsSinceEpoch());
    QCryptographicHash hash(QCryptographicHash::Sha1);
    if (!hash.addData(&file)) return {};
    return hash.result();
}

} // namespace app
