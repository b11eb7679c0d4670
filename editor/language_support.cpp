// LanguageSupport: the help popup at the cursor and the one key filter of every language: F1 (help) and
// Ctrl+Space (completion, when the language has it) are taken before application shortcuts, Escape closes
// the help, and any other key, a click, a scroll or a focus change closes it too.
#include "language_support.h"

#include "help_popup.h"
#include "program_editor.h"

#include <QKeyEvent>

namespace editor {

namespace {
bool isHelpKey(const QKeyEvent* e) {
    return e->key() == Qt::Key_F1 && e->modifiers() == Qt::NoModifier;
}
bool isCompletionKey(const QKeyEvent* e) {
    return e->key() == Qt::Key_Space && e->modifiers() == Qt::ControlModifier;
}
} // namespace

LanguageSupport::LanguageSupport(ProgramEditor& editor, Help help, Outlining outline, bool completes)
    : QObject(&editor), m_editor(editor), m_source(std::move(help)), m_outline(std::move(outline)),
      m_completes(completes),
      m_help(new HelpPopup(&editor)) {
    // Moving the cursor closes the help (a re-layout that reports the same position does not).
    connect(&m_editor, &QsciScintilla::cursorPositionChanged, this, [this] {
        if (m_editor.SendScintilla(QsciScintilla::SCI_GETCURRENTPOS) != m_helpPosition) hideHelp();
    });
    m_editor.installEventFilter(this);
    m_editor.viewport()->installEventFilter(this);
}

void LanguageSupport::detach() {
    delete m_help;
    m_help = nullptr;
    m_editor.removeEventFilter(this);
    m_editor.viewport()->removeEventFilter(this);
    disconnect(&m_editor, nullptr, this, nullptr);
}

QString LanguageSupport::topicAtCursor() const {
    int line = 0, index = 0;
    m_editor.getCursorPosition(&line, &index);
    QString text = m_editor.text(line);
    while (text.endsWith(QLatin1Char('\n')) || text.endsWith(QLatin1Char('\r'))) text.chop(1);
    return m_source.topicAt(text, index);
}

QString LanguageSupport::showHelpAtCursor() {
    const QString topic = topicAtCursor();
    if (topic.isEmpty()) {
        hideHelp();
        return {};
    }
    QString html = m_source.html(topic);
    const bool known = !html.isEmpty();
    if (!known) html = m_source.unknownTopic.arg(topic.toHtmlEscaped());
    const long pos = m_editor.SendScintilla(QsciScintilla::SCI_GETCURRENTPOS);
    const int x = int(m_editor.SendScintilla(QsciScintilla::SCI_POINTXFROMPOSITION, 0, pos));
    const int y = int(m_editor.SendScintilla(QsciScintilla::SCI_POINTYFROMPOSITION, 0, pos));
    const int lineHeight = int(m_editor.SendScintilla(QsciScintilla::SCI_TEXTHEIGHT, 0));
    const QPoint below = m_editor.viewport()->mapToGlobal(QPoint(x, y + lineHeight + 2));
    m_help->showHtml(html, below, m_editor.viewport()->mapToGlobal(QPoint(x, y)).y() - 2);
    m_helpPosition = pos;
    if (known && m_source.opensReference) emit m_editor.helpRequested(topic);
    return topic;
}

void LanguageSupport::hideHelp() {
    if (m_help && m_help->isVisible()) m_help->hide();
}

bool LanguageSupport::showCompletions(bool) {
    return false;
}

bool LanguageSupport::eventFilter(QObject* watched, QEvent* event) {
    switch (event->type()) {
    case QEvent::ShortcutOverride: {
        // Keep F1 (and Ctrl+Space where it completes) for the editor even when a menu action uses them.
        auto* key = static_cast<QKeyEvent*>(event);
        if (isHelpKey(key) || (m_completes && isCompletionKey(key))) {
            event->accept();
            return true;
        }
        break;
    }
    case QEvent::KeyPress: {
        auto* key = static_cast<QKeyEvent*>(event);
        if (isHelpKey(key)) {
            showHelpAtCursor();
            return true;
        }
        if (m_completes && isCompletionKey(key)) {
            hideHelp();
            showCompletions(true);
            return true;
        }
        if (key->key() == Qt::Key_Escape && m_help->isVisible()) {
            hideHelp();
            return true;
        }
        hideHelp();
        // Enter after a complete name ("MA", then Enter) is a new line, not a pick from the list.
        if ((key->key() == Qt::Key_Return || key->key() == Qt::Key_Enter) && m_editor.isListActive() &&
            wordBeforeCursorIsComplete())
            m_editor.cancelList();
        break;
    }
    case QEvent::FocusOut:
    case QEvent::MouseButtonPress:
    case QEvent::Wheel: hideHelp(); break;
    default: break;
    }
    return QObject::eventFilter(watched, event);
}

} // namespace editor
