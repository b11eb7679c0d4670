// Bds5Language: wiring of lexer, folding, diagnostics, completion and F1 help into one ProgramEditor.
// Keys are taken in an event filter (F1, Ctrl+Space, and Enter on a finished word while the list is open),
// and F1/Ctrl+Space win over application shortcuts while the editor has focus.
#include "bds5_language.h"

#include "bds5_completion.h"
#include "bds5_diagnostics.h"
#include "bds5_help.h"
#include "help_popup.h"
#include "program_editor.h"

#include "drive_core/catalog/bds5_catalog.h"

#include <QKeyEvent>

namespace editor {

namespace {

bool isWordByte(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
}

bool isHelpKey(const QKeyEvent* e) {
    return e->key() == Qt::Key_F1 && e->modifiers() == Qt::NoModifier;
}
bool isCompletionKey(const QKeyEvent* e) {
    return e->key() == Qt::Key_Space && e->modifiers() == Qt::ControlModifier;
}

// A word that already names a command or variable (X12 included).
bool isCompleteName(const QByteArray& word) {
    if (word.isEmpty()) return false;
    const std::string upper = word.toUpper().toStdString();
    if (drive_core::catalog::bds5::findVariable(upper)) return true;
    for (const Bds5Completion& item : bds5Completions(QString::fromLatin1(word)))
        if (item.insert.compare(QString::fromLatin1(word), Qt::CaseInsensitive) == 0) return true;
    return false;
}

} // namespace

Bds5Language* Bds5Language::install(ProgramEditor& editor) {
    if (Bds5Language* existing = of(&editor)) return existing;
    return new Bds5Language(editor);
}

Bds5Language* Bds5Language::of(const QsciScintilla* editor) {
    return editor ? editor->findChild<Bds5Language*>(QString(), Qt::FindDirectChildrenOnly) : nullptr;
}

void Bds5Language::uninstall(ProgramEditor& editor) {
    Bds5Language* language = of(&editor);
    if (!language) return;
    language->m_diagnostics->clear();
    delete language->m_diagnostics;
    delete language->m_help;
    editor.setFolding(QsciScintilla::NoFoldStyle, kFoldMargin);
    editor.removeEventFilter(language);
    editor.viewport()->removeEventFilter(language);
    delete language;
}

Bds5Language::Bds5Language(ProgramEditor& editor)
    : QObject(&editor), m_editor(editor), m_lexer(new Bds5Lexer), m_diagnostics(nullptr),
      m_help(new HelpPopup(&editor)) {
    m_editor.setLanguageLexer(m_lexer);
    m_editor.setFolding(QsciScintilla::BoxedTreeFoldStyle, kFoldMargin);
    m_diagnostics = new Bds5Diagnostics(m_editor);
    setTheme(Bds5Lexer::themeFromSettings());

    m_editor.SendScintilla(QsciScintilla::SCI_AUTOCSETIGNORECASE, 1);
    m_editor.SendScintilla(QsciScintilla::SCI_AUTOCSETMAXHEIGHT, 10);
    connect(&m_editor, &QsciScintilla::SCN_CHARADDED, this, &Bds5Language::charAdded);
    connect(&m_editor, &QsciScintilla::userListActivated, this, &Bds5Language::completionChosen);
    // Moving the cursor closes the help (a re-layout that reports the same position does not).
    connect(&m_editor, &QsciScintilla::cursorPositionChanged, this, [this] {
        if (m_editor.SendScintilla(QsciScintilla::SCI_GETCURRENTPOS) != m_helpPosition) hideHelp();
    });
    m_editor.installEventFilter(this);
    m_editor.viewport()->installEventFilter(this);
}

void Bds5Language::setTheme(Bds5Lexer::Theme theme) {
    const bool dark = theme == Bds5Lexer::Theme::Dark;
    m_lexer->setTheme(theme);
    m_lexer->applyStyles(m_editor.font());
    const QColor margin = dark ? QColor(0x25, 0x25, 0x26) : QColor(0xf0, 0xf0, 0xf0);
    m_editor.setMarginsBackgroundColor(margin);
    m_editor.setMarginsForegroundColor(dark ? QColor(0x85, 0x85, 0x85) : QColor(0x80, 0x80, 0x80));
    m_editor.setFoldMarginColors(margin, margin);
    m_editor.setCaretLineBackgroundColor(dark ? QColor(0x2a, 0x2d, 0x2e) : QColor(0xe8, 0xf2, 0xfe));
    m_editor.setCaretForegroundColor(dark ? QColor(0xae, 0xaf, 0xad) : QColor(0x1f, 0x23, 0x28));
    m_editor.setSelectionBackgroundColor(dark ? QColor(0x26, 0x4f, 0x78) : QColor(0xb6, 0xd7, 0xff));
    m_editor.setSelectionForegroundColor(dark ? QColor(0xff, 0xff, 0xff) : QColor(0x1f, 0x23, 0x28));
    m_diagnostics->setDarkTheme(dark);
    m_help->setDarkTheme(dark);
}

QString Bds5Language::topicAtCursor() const {
    int line = 0, index = 0;
    m_editor.getCursorPosition(&line, &index);
    QString text = m_editor.text(line);
    while (text.endsWith(QLatin1Char('\n')) || text.endsWith(QLatin1Char('\r'))) text.chop(1);
    return bds5TopicAt(text, index);
}

QString Bds5Language::showHelpAtCursor() {
    const QString topic = topicAtCursor();
    if (topic.isEmpty()) {
        hideHelp();
        return {};
    }
    QString html = bds5HelpHtml(topic);
    const bool known = !html.isEmpty();
    if (!known)
        html = tr("<b>%1</b> &nbsp;is not a BDS5 command, variable or error number.").arg(topic.toHtmlEscaped());
    const long pos = m_editor.SendScintilla(QsciScintilla::SCI_GETCURRENTPOS);
    const int x = int(m_editor.SendScintilla(QsciScintilla::SCI_POINTXFROMPOSITION, 0, pos));
    const int y = int(m_editor.SendScintilla(QsciScintilla::SCI_POINTYFROMPOSITION, 0, pos));
    const int lineHeight = int(m_editor.SendScintilla(QsciScintilla::SCI_TEXTHEIGHT, 0));
    const QPoint below = m_editor.viewport()->mapToGlobal(QPoint(x, y + lineHeight + 2));
    m_help->showHtml(html, below, m_editor.viewport()->mapToGlobal(QPoint(x, y)).y() - 2);
    m_helpPosition = pos;
    if (known) emit m_editor.helpRequested(topic);
    return topic;
}

void Bds5Language::hideHelp() {
    if (m_help->isVisible()) m_help->hide();
}

long Bds5Language::wordStartBeforeCursor() const {
    const long pos = m_editor.SendScintilla(QsciScintilla::SCI_GETCURRENTPOS);
    long start = pos;
    while (start > 0 && isWordByte(char(m_editor.SendScintilla(QsciScintilla::SCI_GETCHARAT, start - 1)))) --start;
    return start;
}

bool Bds5Language::cursorInCommentOrString() const {
    const long pos = m_editor.SendScintilla(QsciScintilla::SCI_GETCURRENTPOS);
    if (pos == 0) return false;
    // Style the line first: the character just typed may not be styled yet.
    m_editor.SendScintilla(QsciScintilla::SCI_COLOURISE, 0, pos);
    const int style = int(m_editor.SendScintilla(QsciScintilla::SCI_GETSTYLEAT, pos - 1));
    return style == Bds5Comment || style == Bds5String;
}

bool Bds5Language::showCompletions(bool explicitRequest) {
    const long pos = m_editor.SendScintilla(QsciScintilla::SCI_GETCURRENTPOS);
    const long start = wordStartBeforeCursor();
    QByteArray word(pos - start + 1, '\0');
    if (pos > start) m_editor.SendScintilla(QsciScintilla::SCI_GETTEXTRANGE, start, pos, word.data());
    word.chop(1);
    if (!word.isEmpty() && word.front() >= '0' && word.front() <= '9') return false; // a number
    if (!explicitRequest && word.size() < kCompletionMinLetters) return false;
    const auto items = bds5Completions(QString::fromLatin1(word));
    if (items.empty()) return false;
    // A finished word with nothing longer to offer needs no list (ENDIF, then Enter).
    if (!explicitRequest && items.size() == 1 &&
        items.front().insert.compare(QString::fromLatin1(word), Qt::CaseInsensitive) == 0)
        return false;
    QStringList rows;
    rows.reserve(qsizetype(items.size()));
    for (const Bds5Completion& item : items) rows << item.display;
    m_editor.showUserList(kCompletionListId, rows);
    return true;
}

void Bds5Language::charAdded(int ch) {
    // Digits complete nothing new: X1, TMR2 are typed, not picked.
    const bool letter = (ch >= 'A' && ch <= 'Z') || (ch >= 'a' && ch <= 'z') || ch == '_';
    if (!letter || m_editor.isListActive() || cursorInCommentOrString()) return;
    showCompletions(false);
}

void Bds5Language::completionChosen(int id, const QString& text) {
    if (id != kCompletionListId) return;
    const QString shown = text.section(kBds5CompletionSeparator, 0, 0);
    QString insert = shown;
    for (const Bds5Completion& item : bds5Completions(shown))
        if (item.display == text) insert = item.insert;
    const long pos = m_editor.SendScintilla(QsciScintilla::SCI_GETCURRENTPOS);
    const long start = wordStartBeforeCursor();
    QByteArray typed(pos - start + 1, '\0');
    if (pos > start) m_editor.SendScintilla(QsciScintilla::SCI_GETTEXTRANGE, start, pos, typed.data());
    typed.chop(1);
    // Picking the X1..X250 row after typing X12 keeps the 12.
    if (typed.size() > insert.size() && typed.toUpper().startsWith(insert.toLatin1()))
        insert = QString::fromLatin1(typed.toUpper());
    const QByteArray bytes = insert.toLatin1();
    m_editor.SendScintilla(QsciScintilla::SCI_SETTARGETRANGE, start, pos);
    m_editor.SendScintilla(QsciScintilla::SCI_REPLACETARGET, static_cast<unsigned long>(bytes.size()),
                           bytes.constData());
    m_editor.SendScintilla(QsciScintilla::SCI_GOTOPOS, static_cast<unsigned long>(start + bytes.size()));
}

bool Bds5Language::eventFilter(QObject* watched, QEvent* event) {
    switch (event->type()) {
    case QEvent::ShortcutOverride: {
        // Keep F1 and Ctrl+Space for the editor even when a menu action uses them.
        auto* key = static_cast<QKeyEvent*>(event);
        if (isHelpKey(key) || isCompletionKey(key)) {
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
        if (isCompletionKey(key)) {
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
        if ((key->key() == Qt::Key_Return || key->key() == Qt::Key_Enter) && m_editor.isListActive()) {
            const long pos = m_editor.SendScintilla(QsciScintilla::SCI_GETCURRENTPOS);
            const long start = wordStartBeforeCursor();
            QByteArray word(pos - start + 1, '\0');
            if (pos > start) m_editor.SendScintilla(QsciScintilla::SCI_GETTEXTRANGE, start, pos, word.data());
            word.chop(1);
            if (isCompleteName(word)) m_editor.cancelList();
        }
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
