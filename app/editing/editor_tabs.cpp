// EditorTabs: tab bookkeeping.
#include "editor_tabs.h"

#include "editor/bds5_language.h"
#include "editor/mpl_language.h"
#include "editor/program_editor.h"

#include <QFileInfo>
#include <QIcon>
#include <QTabBar>

namespace app {

namespace {
const char* const kUntitledProperty = "servodeskUntitledName";
const char* const kTypeProperty = "servodeskFileType";
} // namespace

EditorTabs::EditorTabs(QWidget* parent) : QTabWidget(parent) {
    setObjectName(QStringLiteral("editorTabs"));
    setDocumentMode(true);
    setTabsClosable(true);
    setMovable(true);
    setElideMode(Qt::ElideMiddle);
    setUsesScrollButtons(true);
    tabBar()->setExpanding(false);
    connect(this, &QTabWidget::currentChanged, this, [this] {
        emit currentEditorChanged(currentEditor());
        emit currentDocumentChanged();
    });
}

editor::ProgramEditor* EditorTabs::addEditor(const QString& untitledName) {
    auto* editor = new editor::ProgramEditor(this);
    editor->setProperty(kUntitledProperty, untitledName);
    editor->setProperty(kTypeProperty, -1);
    connect(editor, &QsciScintilla::modificationChanged, this, [this, editor] {
        refreshTab(editor);
        if (editor == currentEditor()) emit currentDocumentChanged();
    });
    emit editorCreated(editor);
    const int index = addTab(editor, QString());
    refreshTab(editor);
    setCurrentIndex(index);
    return editor;
}

void EditorTabs::removeEditor(editor::ProgramEditor* editor) {
    const int index = indexOf(editor);
    if (index < 0) return;
    removeTab(index);
    delete editor;
}

editor::ProgramEditor* EditorTabs::currentEditor() const {
    return qobject_cast<editor::ProgramEditor*>(currentWidget());
}

editor::ProgramEditor* EditorTabs::editorAt(int index) const {
    return qobject_cast<editor::ProgramEditor*>(widget(index));
}

QList<editor::ProgramEditor*> EditorTabs::editors() const {
    QList<editor::ProgramEditor*> all;
    for (int i = 0; i < count(); ++i)
        if (auto* editor = editorAt(i)) all.append(editor);
    return all;
}

int EditorTabs::indexOfFile(const QString& path) const {
    const QFileInfo wanted(path);
    const QString canonical = wanted.canonicalFilePath();
    for (int i = 0; i < count(); ++i) {
        const auto* editor = editorAt(i);
        if (!editor || editor->filePath().isEmpty()) continue;
        const QFileInfo info(editor->filePath());
        if (canonical.isEmpty() ? info.absoluteFilePath() == wanted.absoluteFilePath()
                                : info.canonicalFilePath() == canonical)
            return i;
    }
    return -1;
}

QString EditorTabs::displayName(const editor::ProgramEditor* editor) const {
    if (!editor) return QString();
    return editor->filePath().isEmpty() ? editor->property(kUntitledProperty).toString()
                                        : QFileInfo(editor->filePath()).fileName();
}

void EditorTabs::setUntitledName(editor::ProgramEditor* editor, const QString& name) {
    editor->setProperty(kUntitledProperty, name);
    refreshTab(editor);
    if (editor == currentEditor()) emit currentDocumentChanged();
}

QString EditorTabs::freeUntitledName(FileType type) const {
    const QString base = untitledName(type);
    const QFileInfo parts(base);
    QStringList taken;
    for (const auto* editor : editors()) taken << displayName(editor);
    QString name = base;
    for (int n = 2; taken.contains(name); ++n)
        name = QStringLiteral("%1-%2.%3").arg(parts.completeBaseName()).arg(n).arg(parts.suffix());
    return name;
}

FileType EditorTabs::fileType(const editor::ProgramEditor* editor) const {
    return fileTypeOf(displayName(editor));
}

void EditorTabs::refreshTab(editor::ProgramEditor* editor) {
    const int index = indexOf(editor);
    const FileType type = fileType(editor);
    applyLexer(editor, type);
    if (index < 0) return;
    const QString name = displayName(editor);
    setTabText(index, editor->isModified() ? name + QLatin1Char('*') : name);
    setTabIcon(index, QIcon(fileTypeIcon(type)));
    setTabToolTip(index, editor->filePath().isEmpty() ? tr("%1 (not saved yet)").arg(fileTypeName(type))
                                                      : tr("%1 \u2014 %2").arg(fileTypeName(type), editor->filePath()));
}

void EditorTabs::applyLexer(editor::ProgramEditor* editor, FileType type) {
    // Programs and variable sets are BDS5 text, .mpl files MPL; captures and other files are shown plain.
    enum Language { Plain = 0, Bds5 = 1, Mpl = 2 };
    const int wanted = (type == FileType::Program || type == FileType::Variables) ? Bds5
                       : type == FileType::MplProgram                            ? Mpl
                                                                                 : Plain;
    if (editor->property(kTypeProperty).toInt() == wanted) return;
    editor->setProperty(kTypeProperty, wanted);
    QsciLexer* old = editor->lexer();
    editor::Bds5Language::uninstall(*editor);
    editor::MplLanguage::uninstall(*editor);
    if (wanted == Bds5) {
        editor::Bds5Language::install(*editor); // lexer, folding, diagnostics, completion, F1 help
    } else if (wanted == Mpl) {
        editor::MplLanguage::install(*editor); // MPL lexer, folding, program check, F1 help (issue 9)
    } else if (!editor::LanguageSupport::of(editor)) {
        editor->setLexer(nullptr); // plain text; a language a workspace installed (ServoBASIC) keeps its lexer
    }
    if (old && old != editor->lexer()) old->deleteLater();
}

} // namespace app
