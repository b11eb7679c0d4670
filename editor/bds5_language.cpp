// Bds5Language: wiring of lexer, folding, diagnostics and completion into one ProgramEditor; F1 help and
// the key handling are LanguageSupport's, fed with the BDS5 catalog's help.
#include "bds5_language.h"

#include "bds5_completion.h"
#include "bds5_diagnostics.h"
#include "bds5_help.h"
#include "bds5_outline.h"
#include "help_popup.h"
#include "program_editor.h"

#include "drive_core/catalog/bds5_catalog.h"

namespace editor {

namespace {

bool isWordByte(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
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

Bds5Language::Bds5Language(ProgramEditor& editor)
    : LanguageSupport(
          editor,
          {&bds5TopicAt, &bds5HelpHtml, tr("<b>%1</b> &nbsp;is not a BDS5 command, variable or error number."), true},
          {&bds5Outline, tr("No labels (10$) or tasks (POWER-UP$, A$ \u2026) in this program yet.")}, true),
      m_lexer(new Bds5Lexer), m_diagnostics(nullptr) {
    m_editor.setLanguageLexer(m_lexer);
    m_editor.setFolding(QsciScintilla::BoxedTreeFoldStyle, kFoldMargin);
    m_diagnostics = new Bds5Diagnostics(m_editor);
    setTheme(Bds5Lexer::themeFromSettings());

    m_editor.SendScintilla(QsciScintilla::SCI_AUTOCSETIGNORECASE, 1);
    m_editor.SendScintilla(QsciScintilla::SCI_AUTOCSETMAXHEIGHT, 10);
    connect(&m_editor, &QsciScintilla::SCN_CHARADDED, this, &Bds5Language::charAdded);
    connect(&m_editor, &QsciScintilla::userListActivated, this, &Bds5Language::completionChosen);
}

void Bds5Language::detach() {
    m_diagnostics->clear();
    delete m_diagnostics;
    m_diagnostics = nullptr;
    m_editor.setFolding(QsciScintilla::NoFoldStyle, kFoldMargin);
    LanguageSupport::detach();
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
    helpPopup()->setDarkTheme(dark);
}

long Bds5Language::wordStartBeforeCursor() const {
    const long pos = m_editor.SendScintilla(QsciScintilla::SCI_GETCURRENTPOS);
    long start = pos;
    while (start > 0 && isWordByte(char(m_editor.SendScintilla(QsciScintilla::SCI_GETCHARAT, start - 1)))) --start;
    return start;
}

QByteArray Bds5Language::wordBeforeCursor() const {
    const long pos = m_editor.SendScintilla(QsciScintilla::SCI_GETCURRENTPOS);
    const long start = wordStartBeforeCursor();
    QByteArray word(pos - start + 1, '\0');
    if (pos > start) m_editor.SendScintilla(QsciScintilla::SCI_GETTEXTRANGE, start, pos, word.data());
    word.chop(1);
    return word;
}

bool Bds5Language::wordBeforeCursorIsComplete() const {
    return isCompleteName(wordBeforeCursor());
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
    const QByteArray word = wordBeforeCursor();
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
    const QByteArray typed = wordBeforeCursor();
    // Picking the X1..X250 row after typing X12 keeps the 12.
    if (typed.size() > insert.size() && typed.toUpper().startsWith(insert.toLatin1()))
        insert = QString::fromLatin1(typed.toUpper());
    const QByteArray bytes = insert.toLatin1();
    m_editor.SendScintilla(QsciScintilla::SCI_SETTARGETRANGE, start, pos);
    m_editor.SendScintilla(QsciScintilla::SCI_REPLACETARGET, static_cast<unsigned long>(bytes.size()),
                           bytes.constData());
    m_editor.SendScintilla(QsciScintilla::SCI_GOTOPOS, static_cast<unsigned long>(start + bytes.size()));
}

} // namespace editor
