// ServoBasicLanguage: the lexer and catalog completion wired into one .bas editor; F1 help and the key
// handling are LanguageSupport's, fed with the SC750 catalog's help.
#include "servobasic_language.h"

#include "program_editor.h"
#include "servobasic_help.h"
#include "servobasic_lexer.h"
#include "servobasic_outline.h"

#include <QStringList>

namespace editor {

ServoBasicLanguage::ServoBasicLanguage(ProgramEditor& editor)
    : LanguageSupport(editor,
                      {&servoBasicTopicAt, &servoBasicHelpHtml,
                       tr("<b>%1</b> &nbsp;is not a ServoBASIC Plus statement, function or predefined variable."),
                       false},
                      {&servoBasicOutline, tr("No labels (Name:), SUBs or INTERRUPT routines in this program yet.")},
                      true),
      m_lexer(new ServoBasicLexer) {
    m_editor.setLanguageLexer(m_lexer);
    m_lexer->applyStyles(m_editor.font());
    connect(&m_editor, &QsciScintilla::SCN_CHARADDED, this, [this](int) {
        if (wordBeforeCursor().size() >= kCompletionMinLetters) showCompletions(false);
    });
    connect(&m_editor, &QsciScintilla::userListActivated, this, &ServoBasicLanguage::completionChosen);
}

void ServoBasicLanguage::detach() {
    if (m_editor.lexer() == m_lexer) {
        m_editor.setLexer(nullptr);
        m_lexer->deleteLater();
    }
    LanguageSupport::detach();
}

QString ServoBasicLanguage::wordBeforeCursor() const {
    int line = 0, index = 0;
    m_editor.getCursorPosition(&line, &index);
    const QString text = m_editor.text(line).left(index);
    if (text.contains(QLatin1Char('\'')) || text.count(QLatin1Char('"')) % 2 == 1) return {}; // comment, string
    int start = int(text.size());
    while (start > 0 && isServoBasicWordChar(text[start - 1])) --start;
    return text.mid(start);
}

bool ServoBasicLanguage::showCompletions(bool) {
    const QStringList matches = servoBasicCompletions(wordBeforeCursor());
    if (matches.isEmpty()) return false;
    m_editor.showUserList(kCompletionListId, matches);
    return true;
}

void ServoBasicLanguage::completionChosen(int id, const QString& text) {
    if (id != kCompletionListId) return;
    const long length = long(wordBeforeCursor().toUtf8().size());
    const long start = m_editor.SendScintilla(QsciScintilla::SCI_GETCURRENTPOS) - length;
    m_editor.SendScintilla(QsciScintilla::SCI_DELETERANGE, static_cast<unsigned long>(start), length);
    m_editor.insert(text);
    m_editor.SendScintilla(QsciScintilla::SCI_GOTOPOS, static_cast<unsigned long>(start + long(text.toUtf8().size())));
}

} // namespace editor
