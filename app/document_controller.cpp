// DocumentController: file actions with non-blocking dialogs.
#include "document_controller.h"

#include "editor/program_editor.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>

namespace app {

namespace {
const QString kFilter = QStringLiteral("BDS5 programs (*.bds *.BDS);;All files (*)");
const QString kUntitled = QStringLiteral("untitled.bds");
} // namespace

DocumentController::DocumentController(editor::ProgramEditor& editor, QWidget* dialogParent)
    : QObject(dialogParent), m_editor(editor), m_dialogParent(dialogParent), m_untitledName(kUntitled) {}

void DocumentController::openTemplate(const QString& path, const QString& displayName) {
    if (const auto result = m_editor.loadFile(path); !result.ok) {
        showError(result.message);
        return;
    }
    m_editor.forgetFilePath();
    m_untitledName = displayName;
    emit documentChanged();
}

void DocumentController::newDocument() {
    whenSafeToDiscard([this] {
        m_editor.newDocument();
        m_untitledName = kUntitled;
        emit documentChanged();
    });
}

void DocumentController::open() {
    whenSafeToDiscard([this] {
        auto* dialog = new QFileDialog(m_dialogParent, tr("Open Program"), QDir::homePath(), kFilter);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->setAcceptMode(QFileDialog::AcceptOpen);
        dialog->setFileMode(QFileDialog::ExistingFile);
        connect(dialog, &QFileDialog::fileSelected, this, &DocumentController::loadFrom);
        dialog->open();
    });
}

void DocumentController::save() {
    saveThen([] {});
}

void DocumentController::saveAs() {
    saveAsThen([] {});
}

void DocumentController::whenSafeToDiscard(std::function<void()> proceed) {
    if (!m_editor.isModified()) {
        proceed();
        return;
    }
    auto* box =
        new QMessageBox(QMessageBox::Warning, tr("Unsaved Changes"),
                        tr("%1 has unsaved changes. Save them?").arg(displayName()),
                        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, m_dialogParent);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setDefaultButton(QMessageBox::Save);
    connect(box, &QMessageBox::finished, this, [this, box, proceed = std::move(proceed)](int) {
        const QMessageBox::StandardButton answer = box->standardButton(box->clickedButton());
        if (answer == QMessageBox::Save)
            saveThen(proceed);
        else if (answer == QMessageBox::Discard)
            proceed();
    });
    box->open();
}

QString DocumentController::displayName() const {
    return m_editor.filePath().isEmpty() ? m_untitledName : QFileInfo(m_editor.filePath()).fileName();
}

void DocumentController::saveThen(std::function<void()> then) {
    if (m_editor.filePath().isEmpty()) {
        saveAsThen(std::move(then));
        return;
    }
    if (writeTo(m_editor.filePath())) then();
}

void DocumentController::saveAsThen(std::function<void()> then) {
    const QString start =
        m_editor.filePath().isEmpty() ? QDir::home().filePath(m_untitledName) : m_editor.filePath();
    auto* dialog = new QFileDialog(m_dialogParent, tr("Save Program As"), start, kFilter);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setAcceptMode(QFileDialog::AcceptSave);
    dialog->setDefaultSuffix(QStringLiteral("bds"));
    connect(dialog, &QFileDialog::fileSelected, this, [this, then = std::move(then)](const QString& path) {
        if (writeTo(path)) then();
    });
    dialog->open();
}

bool DocumentController::writeTo(const QString& path) {
    const auto result = m_editor.saveFile(path);
    if (!result.ok) {
        showError(result.message);
        return false;
    }
    emit documentChanged();
    emit statusMessage(tr("Saved %1").arg(QDir::toNativeSeparators(path)));
    return true;
}

void DocumentController::loadFrom(const QString& path) {
    const auto result = m_editor.loadFile(path);
    if (!result.ok) {
        showError(result.message);
        return;
    }
    emit documentChanged();
    emit statusMessage(tr("Opened %1").arg(QDir::toNativeSeparators(path)));
}

void DocumentController::showError(const QString& message) {
    auto* box =
        new QMessageBox(QMessageBox::Critical, tr("ServoDesk"), message, QMessageBox::Ok, m_dialogParent);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

} // namespace app
