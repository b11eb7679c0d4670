// DocumentController: file actions over the tabs, with non-blocking dialogs.
#include "document_controller.h"

#include "editor_tabs.h"
#include "recent_files.h"

#include "editor/program_editor.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QSettings>

namespace app {

DocumentController::DocumentController(EditorTabs& tabs, RecentFiles& recent, QWidget* dialogParent)
    : QObject(dialogParent), m_tabs(tabs), m_recent(recent), m_dialogParent(dialogParent) {
    connect(&m_tabs, &QTabWidget::tabCloseRequested, this, &DocumentController::closeTab);
    connect(&m_tabs, &EditorTabs::currentEditorChanged, this, &DocumentController::documentChanged);
}

void DocumentController::openTemplate(const QString& path, const QString& displayName) {
    editor::ProgramEditor* editor = m_tabs.addEditor(displayName);
    if (const auto result = editor->loadFile(path); !result.ok) {
        showError(result.message);
        return;
    }
    editor->forgetFilePath();
    m_tabs.refreshTab(editor);
    emit documentChanged();
}

void DocumentController::newDocument() {
    m_tabs.addEditor(m_tabs.freeUntitledName(FileType::Program));
    emit documentChanged();
}

void DocumentController::open() {
    auto* dialog = new QFileDialog(m_dialogParent, tr("Open"), startDirectory(), openFilter());
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setAcceptMode(QFileDialog::AcceptOpen);
    dialog->setFileMode(QFileDialog::ExistingFiles);
    connect(dialog, &QFileDialog::filesSelected, this, [this](const QStringList& paths) {
        for (const QString& path : paths) openFile(path);
    });
    dialog->open();
}

bool DocumentController::openFile(const QString& path) {
    if (const int index = m_tabs.indexOfFile(path); index >= 0) {
        m_tabs.setCurrentIndex(index);
        m_recent.add(path);
        emit fileOpenedAgain(m_tabs.editorAt(index)); // the disk's content, or a question when it has edits
        return true;
    }
    editor::ProgramEditor* editor = m_tabs.addEditor(QFileInfo(path).fileName());
    if (const auto result = editor->loadFile(path); !result.ok) {
        m_tabs.removeEditor(editor);
        m_recent.remove(path);
        showError(result.message);
        return false;
    }
    tabNowShows(editor, path, &DocumentController::fileLoaded, tr("Opened %1"));
    return true;
}

void DocumentController::save() {
    saveThen(m_tabs.currentEditor(), [] {});
}

void DocumentController::saveAs() {
    saveAsThen(m_tabs.currentEditor(), [] {});
}

void DocumentController::closeTab(int index) {
    QPointer<editor::ProgramEditor> editor = m_tabs.editorAt(index);
    if (!editor) return;
    whenSafeToDiscard(editor, [this, editor] {
        if (!editor) return;
        m_tabs.removeEditor(editor);
        if (m_tabs.count() == 0) newDocument();
        emit documentChanged();
    });
}

void DocumentController::closeCurrentTab() {
    closeTab(m_tabs.currentIndex());
}

void DocumentController::whenSafeToDiscard(std::function<void()> proceed) {
    whenSafeToDiscard(m_tabs.currentEditor(), std::move(proceed));
}

void DocumentController::whenSafeToDiscard(editor::ProgramEditor* editor, std::function<void()> proceed) {
    if (!editor || !editor->isModified()) {
        proceed();
        return;
    }
    m_tabs.setCurrentWidget(editor); // show what the question is about
    auto* box = new QMessageBox(QMessageBox::Warning, tr("Unsaved Changes"),
                                tr("%1 has unsaved changes. Save them?").arg(m_tabs.displayName(editor)),
                                QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, m_dialogParent);
    box->setObjectName(QStringLiteral("unsavedChangesBox"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setDefaultButton(QMessageBox::Save);
    QPointer<editor::ProgramEditor> guarded = editor;
    connect(box, &QMessageBox::finished, this, [this, box, guarded, proceed = std::move(proceed)](int) {
        const QMessageBox::StandardButton answer = box->standardButton(box->clickedButton());
        if (answer == QMessageBox::Save && guarded)
            saveThen(guarded, proceed);
        else if (answer == QMessageBox::Discard)
            proceed();
    });
    box->open();
}

void DocumentController::whenAllSafeToDiscard(std::function<void()> proceed) {
    QList<QPointer<editor::ProgramEditor>> all;
    for (auto* editor : m_tabs.editors()) all.append(editor);
    askEach(std::move(all), std::move(proceed));
}

bool DocumentController::hasUnsavedChanges() const {
    for (const auto* editor : m_tabs.editors())
        if (editor->isModified()) return true;
    return false;
}

QString DocumentController::displayName() const {
    return m_tabs.displayName(m_tabs.currentEditor());
}

QString DocumentController::startDirectory() const {
    if (const auto* editor = m_tabs.currentEditor(); editor && !editor->filePath().isEmpty())
        return QFileInfo(editor->filePath()).absolutePath();
    const QString last = QSettings().value(kLastDirKey).toString();
    return !last.isEmpty() && QFileInfo(last).isDir() ? last : QDir::homePath();
}

void DocumentController::rememberDirectory(const QString& path) {
    QSettings().setValue(kLastDirKey, QFileInfo(path).absolutePath());
}

void DocumentController::askEach(QList<QPointer<editor::ProgramEditor>> remaining, std::function<void()> proceed) {
    while (!remaining.isEmpty() && (!remaining.first() || !remaining.first()->isModified())) remaining.removeFirst();
    if (remaining.isEmpty()) {
        proceed();
        return;
    }
    editor::ProgramEditor* first = remaining.takeFirst();
    whenSafeToDiscard(
        first, [this, remaining = std::move(remaining), proceed = std::move(proceed)] { askEach(remaining, proceed); });
}

void DocumentController::saveThen(editor::ProgramEditor* editor, std::function<void()> then) {
    if (!editor) return;
    if (editor->filePath().isEmpty()) {
        saveAsThen(editor, std::move(then));
        return;
    }
    if (writeTo(editor, editor->filePath())) then();
}

void DocumentController::saveAsThen(editor::ProgramEditor* editor, std::function<void()> then) {
    if (!editor) return;
    const FileType type = m_tabs.fileType(editor);
    const QString start =
        editor->filePath().isEmpty() ? QDir(startDirectory()).filePath(m_tabs.displayName(editor)) : editor->filePath();
    auto* dialog =
        new QFileDialog(m_dialogParent, tr("Save %1 As").arg(m_tabs.displayName(editor)), start, saveFilter(type));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setAcceptMode(QFileDialog::AcceptSave);
    dialog->setDefaultSuffix(defaultSuffix(type));
    QPointer<editor::ProgramEditor> guarded = editor;
    connect(dialog, &QFileDialog::fileSelected, this, [this, guarded, then = std::move(then)](const QString& path) {
        if (guarded && writeTo(guarded, path)) then();
    });
    dialog->open();
}

bool DocumentController::writeTo(editor::ProgramEditor* editor, const QString& path) {
    const auto result = editor->saveFile(path);
    if (!result.ok) {
        showError(result.message);
        return false;
    }
    tabNowShows(editor, path, &DocumentController::fileSaved, tr("Saved %1"));
    return true;
}

// A tab that has just been read from or written to path: its title, the recent list and the next dialog's
// folder; then done (fileLoaded or fileSaved) and the status (with %1 for the path).
void DocumentController::tabNowShows(editor::ProgramEditor* editor, const QString& path, FileSignal done,
                                     const QString& status) {
    m_tabs.refreshTab(editor);
    m_recent.add(path);
    rememberDirectory(path);
    emit(this->*done)(editor, path);
    emit documentChanged();
    emit statusMessage(status.arg(QDir::toNativeSeparators(path)));
}

void DocumentController::showError(const QString& message) {
    auto* box = new QMessageBox(QMessageBox::Critical, tr("ServoDesk"), message, QMessageBox::Ok, m_dialogParent);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

} // namespace app
