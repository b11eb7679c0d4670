// EditorArea: composition of tabs, find bar, recovery bar and the editor commands.
#include "editor_area.h"

#include "autosaver.h"
#include "disk_change_bar.h"
#include "disk_watcher.h"
#include "document_controller.h"
#include "editor_actions.h"
#include "editor_tabs.h"
#include "recent_files.h"
#include "recovery_bar.h"

#include "editor/editor_size.h"
#include "editor/find_bar.h"
#include "editor/key_chord_filter.h"
#include "editor/keymap.h"
#include "editor/program_editor.h"
#include "resources/resources.h"

#include <QDialog>
#include <QDialogButtonBox>
#include <QFile>
#include <QFileInfo>
#include <QFontDatabase>
#include <QFrame>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QPlainTextEdit>
#include <QSettings>
#include <QStatusBar>
#include <QVBoxLayout>

namespace app {

using editor::Keymap;

EditorArea::EditorArea(QWidget* parent)
    : QWidget(parent), m_store(std::make_unique<RecoveryStore>()), m_recoveryBar(new RecoveryBar(this)),
      m_tabs(new EditorTabs(this)), m_findBar(new editor::FindBar(this)), m_recent(new RecentFiles(this)),
      m_documents(new DocumentController(*m_tabs, *m_recent, this)),
      m_actions(new EditorActions(*m_tabs, *m_documents, *m_findBar, this)), m_chords(new editor::KeyChordFilter(this)),
      m_recentMenu(new QMenu(tr("Open &Recent"), this)), m_autosaver(std::make_unique<Autosaver>(*m_tabs, *m_store)) {
    setObjectName(QStringLiteral("editorArea"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(m_recoveryBar);
    m_diskBar = new DiskChangeBar(this);
    layout->addWidget(m_diskBar);
    layout->addWidget(m_tabs, 1);
    layout->addWidget(m_findBar);

    connect(m_tabs, &EditorTabs::editorCreated, this, &EditorArea::setUpEditor);
    connect(m_tabs, &EditorTabs::currentEditorChanged, this, &EditorArea::editorChanged);
    connect(m_tabs, &EditorTabs::currentDocumentChanged, this, &EditorArea::currentDocumentChanged);
    connect(m_documents, &DocumentController::documentChanged, this, &EditorArea::currentDocumentChanged);
    connect(m_documents, &DocumentController::statusMessage, this, &EditorArea::statusMessage);
    connect(m_actions, &EditorActions::statusMessage, this, &EditorArea::statusMessage);
    connect(m_recent, &RecentFiles::openRequested, m_documents, &DocumentController::openFile);
    connect(m_recentMenu, &QMenu::aboutToShow, this, [this] { m_recent->fillMenu(m_recentMenu); });
    connect(m_chords, &editor::KeyChordFilter::commandTriggered, this,
            [this](editor::EditorCommand command) { m_actions->run(command); });
    connect(m_chords, &editor::KeyChordFilter::pendingChanged, this, &EditorArea::showPendingKeys);
    connect(m_chords, &editor::KeyChordFilter::unknownChord, this,
            [this](const QString& keys) { emit statusMessage(tr("%1 is not an editor command").arg(keys)); });
    connect(m_recoveryBar, &RecoveryBar::restoreRequested, this, &EditorArea::restoreRecovered);
    connect(m_recoveryBar, &RecoveryBar::discardRequested, this, &EditorArea::discardRecovered);
    m_diskWatcher = new DiskWatcher(*m_tabs, *m_diskBar, this);
    connect(m_documents, &DocumentController::fileLoaded, m_diskWatcher, &DiskWatcher::track);
    connect(m_documents, &DocumentController::fileSaved, m_diskWatcher, &DiskWatcher::track);
    connect(m_documents, &DocumentController::fileOpenedAgain, m_diskWatcher, &DiskWatcher::reopened);
    connect(m_diskWatcher, &DiskWatcher::statusMessage, this, &EditorArea::statusMessage);

    m_recent->fillMenu(m_recentMenu);
    reloadKeymap();
    m_recoveryBar->offer(m_store->orphans());
}

EditorArea::~EditorArea() {
    delete m_diskWatcher; // before the tabs, whose editors it follows, go
}

editor::ProgramEditor* EditorArea::currentEditor() const {
    return m_tabs->currentEditor();
}

QString EditorArea::keymapName() const {
    return m_chords->keymap().name();
}

void EditorArea::applyKeymap(const QString& name) {
    const Keymap keymap = Keymap::named(name);
    m_chords->setKeymap(keymap);
    m_actions->setKeymap(keymap);
    showPendingKeys(QString());
}

void EditorArea::reloadKeymap() {
    applyKeymap(QSettings().value(Keymap::kSettingsKey, Keymap::kModern).toString());
}

void EditorArea::fillFileMenu(QMenu* menu) {
    m_actions->fillFileMenu(menu, m_recentMenu);
}

void EditorArea::fillEditMenu(QMenu* menu) {
    m_actions->fillEditMenu(menu);
    menu->addSeparator();
    // A quick switch between the keymaps; Options writes the same setting.
    QAction* classic = menu->addAction(tr("Classic Motion Link &Keys"));
    classic->setObjectName(QStringLiteral("classicKeysAction"));
    classic->setCheckable(true);
    classic->setStatusTip(tr("WordStar-like keys as in Motion Link's editor: ^K^B, ^Q^F, ^L, ^Y ..."));
    connect(menu, &QMenu::aboutToShow, classic,
            [this, classic] { classic->setChecked(keymapName() == Keymap::kClassic); });
    connect(classic, &QAction::triggered, this, [this](bool on) {
        QSettings().setValue(Keymap::kSettingsKey, on ? Keymap::kClassic : Keymap::kModern);
        reloadKeymap();
        emit statusMessage(on ? tr("Classic Motion Link keys") : tr("Modern keys"));
    });
}

void EditorArea::fillSearchMenu(QMenu* menu) {
    m_actions->fillSearchMenu(menu);
}

void EditorArea::installStatusWidgets(QStatusBar* statusBar) {
    m_sizeLabel = new QLabel(statusBar);
    m_sizeLabel->setObjectName(QStringLiteral("editorSizeLabel"));
    m_sizeLabel->setToolTip(tr("Cursor line, and the program's size against Motion Link's 2,000 lines / "
                               "24,000 bytes"));
    m_keysLabel = new QLabel(statusBar);
    m_keysLabel->setObjectName(QStringLiteral("keymapLabel"));
    m_keysLabel->setContentsMargins(6, 0, 6, 0);
    // One cell, left of the drive's cells: "Line 3 of 12 · 240 of 24,000 bytes | Modern keys |".
    auto* cell = new QWidget(statusBar);
    auto* layout = new QHBoxLayout(cell);
    layout->setContentsMargins(0, 0, 0, 0);
    for (QLabel* label : {m_sizeLabel, m_keysLabel}) {
        label->setParent(cell);
        layout->addWidget(label);
        auto* separator = new QFrame(cell);
        separator->setFrameStyle(QFrame::VLine | QFrame::Sunken);
        layout->addWidget(separator);
    }
    statusBar->insertPermanentWidget(0, cell);
    editorChanged(currentEditor());
    showPendingKeys(QString());
}

bool EditorArea::hasUnsavedChanges() const {
    return m_documents->hasUnsavedChanges();
}

void EditorArea::whenSafeToClose(std::function<void()> proceed) {
    m_documents->whenAllSafeToDiscard(std::move(proceed));
}

int EditorArea::restoreRecovered() {
    const QList<RecoveredBuffer> buffers = m_store->orphans();
    for (const RecoveredBuffer& buffer : buffers) {
        // chosen: a file that still exists and is not open yet comes back under its own path (Save writes
        // it); otherwise the text opens unnamed, so nothing is overwritten without asking.
        const bool reopen = !buffer.originalPath.isEmpty() && QFileInfo::exists(buffer.originalPath) &&
                            m_tabs->indexOfFile(buffer.originalPath) < 0;
        editor::ProgramEditor* e = m_tabs->addEditor(buffer.displayName);
        if (reopen && !e->loadFile(buffer.originalPath).ok) e->forgetFilePath();
        e->setText(buffer.text);
        e->setModified(true);
        m_tabs->refreshTab(e);
        m_diskWatcher->track(e); // a file changed on disk from now on asks before the restored text goes
    }
    m_autosaver->flush(); // the restored text is this session's to protect now
    m_store->discardOrphans();
    m_recoveryBar->hide();
    emit currentDocumentChanged();
    emit statusMessage(buffers.size() == 1 ? tr("Restored 1 file: save it to keep the text")
                                           : tr("Restored %1 files: save them to keep the text").arg(buffers.size()));
    return int(buffers.size());
}

void EditorArea::discardRecovered() {
    m_store->discardOrphans();
    m_recoveryBar->hide();
    emit statusMessage(tr("Discarded the unsaved text of the last session"));
}

QWidget* EditorArea::showClassicKeys() {
    auto* dialog = new QDialog(this);
    dialog->setObjectName(QStringLiteral("classicKeysHelp"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowTitle(tr("Classic Editor Keys"));
    auto* text = new QPlainTextEdit(dialog);
    text->setReadOnly(true);
    text->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    QFile file(resources::kClassicKeymapHelp);
    if (file.open(QIODevice::ReadOnly)) text->setPlainText(QString::fromUtf8(file.readAll()));
    auto* layout = new QVBoxLayout(dialog);
    layout->addWidget(text);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
    connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::close);
    layout->addWidget(buttons);
    dialog->resize(text->fontMetrics().horizontalAdvance(QLatin1Char('M')) * 96, 640);
    dialog->show();
    return dialog;
}

QString EditorArea::sizeStatusText() const {
    const auto* e = currentEditor();
    if (!e) return QString();
    const editor::EditorSize& size = m_size;
    int line = 0;
    int index = 0;
    e->getCursorPosition(&line, &index);
    const QLocale locale;
    return tr("Line %1 of %2 \u00b7 %3 of %4 bytes")
        .arg(locale.toString(line + 1), locale.toString(qMax(line + 1, size.lines)),
             locale.toString(qlonglong(size.bytes)), locale.toString(qlonglong(editor::EditorSize::kMaxBytes)));
}

void EditorArea::setUpEditor(editor::ProgramEditor* editor) {
    m_chords->watch(editor);
    // chosen: a new tab re-reads the keymap, so a change written by Options applies without a restart.
    reloadKeymap();
}

void EditorArea::editorChanged(editor::ProgramEditor* editor) {
    disconnect(m_cursorConnection);
    disconnect(m_textConnection);
    m_findBar->setEditor(editor);
    if (editor) {
        m_cursorConnection = connect(editor, &QsciScintilla::cursorPositionChanged, this, &EditorArea::updateSizeLabel);
        m_textConnection = connect(editor, &QsciScintilla::textChanged, this, [this] {
            measure();
            updateSizeLabel();
        });
    }
    measure();
    updateSizeLabel();
    emit currentEditorChanged(editor);
}

void EditorArea::measure() {
    const auto* e = currentEditor();
    m_size = e ? editor::measureText(e->text(), e->eolMode() == QsciScintilla::EolWindows) : editor::EditorSize{};
}

void EditorArea::updateSizeLabel() {
    if (!m_sizeLabel) return;
    m_sizeLabel->setText(sizeStatusText());
    m_sizeLabel->setStyleSheet(m_size.fits() ? QString() : QStringLiteral("color: #b3261e; font-weight: bold;"));
}

void EditorArea::showPendingKeys(const QString& keys) {
    if (!m_keysLabel) return;
    if (!keys.isEmpty()) {
        m_keysLabel->setText(QStringLiteral("<b>%1</b> \u2026").arg(keys.toHtmlEscaped()));
        return;
    }
    m_keysLabel->setText(keymapName() == Keymap::kClassic ? tr("Classic keys") : tr("Modern keys"));
}

} // namespace app
