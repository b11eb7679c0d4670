// MplLanguage: lexer, program check and F1 help wired into one ProgramEditor. F1 is taken in an event
// filter, so it wins over application shortcuts while the editor has focus.
#include "mpl_language.h"

#include "editor/help_popup.h"
#include "editor/mpl_help.h"
#include "editor/mpl_lexer.h"
#include "editor/mpl_line_styler.h"
#include "editor/program_editor.h"

#include <Qsci/qscistyle.h>

#include <QKeyEvent>

namespace app {

namespace {
bool isHelpKey(const QKeyEvent* e) {
    return e->key() == Qt::Key_F1 && e->modifiers() == Qt::NoModifier;
}

QsciStyle annotationStyle(const QFont& base) {
    QFont font = base;
    font.setPointSizeF(font.pointSizeF() * 0.9);
    return QsciStyle(-1, QStringLiteral("MPL check"), QColor(0x9f, 0x1c, 0x24), QColor(0xff, 0xf0, 0xef), font, true);
}
} // namespace

MplLanguage* MplLanguage::install(editor::ProgramEditor& editor) {
    if (MplLanguage* existing = of(&editor)) return existing;
    return new MplLanguage(editor);
}

MplLanguage* MplLanguage::of(const QsciScintilla* editor) {
    return editor ? editor->findChild<MplLanguage*>(QString(), Qt::FindDirectChildrenOnly) : nullptr;
}

void MplLanguage::uninstall(editor::ProgramEditor& editor) {
    MplLanguage* language = of(&editor);
    if (!language) return;
    editor.clearAnnotations();
    delete language->m_help;
    editor.setFolding(QsciScintilla::NoFoldStyle, kFoldMargin);
    editor.removeEventFilter(language);
    editor.viewport()->removeEventFilter(language);
    delete language;
}

MplLanguage::MplLanguage(editor::ProgramEditor& editor)
    : QObject(&editor), m_editor(editor), m_lexer(new editor::MplLexer), m_help(new editor::HelpPopup(&editor)) {
    m_editor.setLanguageLexer(m_lexer);
    m_lexer->applyStyles(m_editor.font());
    m_editor.setFolding(QsciScintilla::BoxedTreeFoldStyle, kFoldMargin);
    m_editor.setAnnotationDisplay(QsciScintilla::AnnotationIndented);
    m_check.setSingleShot(true);
    m_check.setInterval(kCheckDelayMs);
    connect(&m_check, &QTimer::timeout, this, &MplLanguage::checkNow);
    connect(&m_editor, &QsciScintilla::textChanged, &m_check, qOverload<>(&QTimer::start));
    connect(&m_editor, &QsciScintilla::cursorPositionChanged, this, [this] {
        if (m_editor.SendScintilla(QsciScintilla::SCI_GETCURRENTPOS) != m_helpPosition) hideHelp();
    });
    m_editor.installEventFilter(this);
    m_editor.viewport()->installEventFilter(this);
    m_check.start();
}

QString MplLanguage::topicAtCursor() const {
    int line = 0, index = 0;
    m_editor.getCursorPosition(&line, &index);
    QString text = m_editor.text(line);
    while (text.endsWith(QLatin1Char('\n')) || text.endsWith(QLatin1Char('\r'))) text.chop(1);
    return editor::mplTopicAt(text, index);
}

QString MplLanguage::showHelpAtCursor() {
    const QString topic = topicAtCursor();
    if (topic.isEmpty()) {
        hideHelp();
        return {};
    }
    QString html = editor::mplHelpHtml(topic);
    if (html.isEmpty())
        html = tr("<b>%1</b> &nbsp;is not an MPL command, parameter or error code.").arg(topic.toHtmlEscaped());
    const long pos = m_editor.SendScintilla(QsciScintilla::SCI_GETCURRENTPOS);
    const int x = int(m_editor.SendScintilla(QsciScintilla::SCI_POINTXFROMPOSITION, 0, pos));
    const int y = int(m_editor.SendScintilla(QsciScintilla::SCI_POINTYFROMPOSITION, 0, pos));
    const int lineHeight = int(m_editor.SendScintilla(QsciScintilla::SCI_TEXTHEIGHT, 0));
    const QPoint below = m_editor.viewport()->mapToGlobal(QPoint(x, y + lineHeight + 2));
    m_help->showHtml(html, below, m_editor.viewport()->mapToGlobal(QPoint(x, y)).y() - 2);
    m_helpPosition = pos;
    return topic;
}

void MplLanguage::hideHelp() {
    if (m_help->isVisible()) m_help->hide();
}

int MplLanguage::checkNow() {
    m_check.stop();
    m_editor.clearAnnotations();
    const QList<editor::MplDiagnostic> found = editor::checkMplProgram(m_editor.text().toLatin1());
    const QsciStyle style = annotationStyle(m_editor.font());
    for (const editor::MplDiagnostic& d : found) {
        const QString others = m_editor.annotation(d.line);
        const QString text = tr("col %1: %2").arg(d.column + 1).arg(d.message);
        m_editor.annotate(d.line, others.isEmpty() ? text : others + QLatin1Char('\n') + text, style);
    }
    return int(found.size());
}

bool MplLanguage::eventFilter(QObject* watched, QEvent* event) {
    switch (event->type()) {
    case QEvent::ShortcutOverride:
        if (isHelpKey(static_cast<QKeyEvent*>(event))) {
            event->accept();
            return true;
        }
        break;
    case QEvent::KeyPress: {
        auto* key = static_cast<QKeyEvent*>(event);
        if (isHelpKey(key)) {
            showHelpAtCursor();
            return true;
        }
        if (key->key() == Qt::Key_Escape && m_help->isVisible()) {
            hideHelp();
            return true;
        }
        hideHelp();
        break;
    }
    case QEvent::FocusOut:
    case QEvent::MouseButtonPress:
    case QEvent::Wheel: hideHelp(); break;
    default: break;
    }
    return QObject::eventFilter(watched, event);
}

} // namespace app
