// ServoBasicLanguage: lexer, catalog completion and F1 help for .bas editors.
#include "servobasic_language.h"

#include "servobasic_lexer.h"

#include "drive_core/catalog/sc750_catalog.h"
#include "editor/help_popup.h"
#include "editor/program_editor.h"


#include <QKeyEvent>

namespace app {

namespace catalog = drive_core::catalog::sc750;

namespace {
QString str(std::string_view text) {
    return QString::fromLatin1(text.data(), qsizetype(text.size()));
}
QString typeName(catalog::ValueType type) {
    switch (type) {
    case catalog::ValueType::Integer: return QStringLiteral("Integer");
    case catalog::ValueType::Float: return QStringLiteral("Float");
    case catalog::ValueType::String: return QStringLiteral("String");
    }
    return {};
}
bool isWordChar(QChar c) {
    return c.isLetterOrNumber() || c == QLatin1Char('.') || c == QLatin1Char('_') || c == QLatin1Char('$');
}
// Every catalog name, sorted: statements, functions, predefined variables and parameters.
const QStringList& catalogNames() {
    static const QStringList names = [] {
        QStringList all;
        for (const auto& s : catalog::statements()) all << str(s.name);
        for (const auto& f : catalog::functions()) all << str(f.name);
        for (const auto& v : catalog::variables()) all << str(v.name);
        all.sort();
        all.removeDuplicates();
        return all;
    }();
    return names;
}
} // namespace

ServoBasicLanguage* ServoBasicLanguage::install(editor::ProgramEditor& editor) {
    if (auto* existing = of(editor)) return existing;
    return new ServoBasicLanguage(editor);
}

ServoBasicLanguage* ServoBasicLanguage::of(const editor::ProgramEditor& editor) {
    return editor.findChild<ServoBasicLanguage*>(QString(), Qt::FindDirectChildrenOnly);
}

void ServoBasicLanguage::uninstall(editor::ProgramEditor& editor) {
    ServoBasicLanguage* language = of(editor);
    if (!language) return;
    if (editor.lexer() == language->m_lexer) {
        editor.setLexer(nullptr);
        language->m_lexer->deleteLater();
    }
    delete language;
}

ServoBasicLanguage::ServoBasicLanguage(editor::ProgramEditor& editor)
    : QObject(&editor), m_editor(editor), m_lexer(new ServoBasicLexer), m_help(new editor::HelpPopup(&editor)) {
    m_editor.setLanguageLexer(m_lexer);
    m_lexer->applyStyles(m_editor.font());
    connect(&m_editor, &QsciScintilla::SCN_CHARADDED, this, [this](int) {
        if (wordBeforeCursor().size() >= kCompletionMinLetters) showCompletions();
    });
    connect(&m_editor, &QsciScintilla::userListActivated, this, &ServoBasicLanguage::completionChosen);
    m_editor.installEventFilter(this);
}

QString ServoBasicLanguage::helpHtml(const QString& word) {
    const std::string name = word.toUpper().toStdString();
    if (const auto* s = catalog::findStatement(name))
        return QStringLiteral("<b>%1</b> (Statement)<br><b>Syntax:</b> <code>%2</code><br>%3<br><small>Manual %4</small>")
            .arg(str(s->name), str(s->syntax).toHtmlEscaped(), str(s->description).toHtmlEscaped(), str(s->manualLines));
    if (const auto* f = catalog::findFunction(name))
        return QStringLiteral("<b>%1</b> (Function, %2)<br><b>Syntax:</b> <code>%3</code><br>%4<br><small>Manual %5</small>")
            .arg(str(f->name), typeName(f->result), str(f->syntax).toHtmlEscaped(), str(f->description).toHtmlEscaped(),
                 str(f->manualLines));
    if (const auto* v = catalog::findVariable(name)) {
        const QString kind = v->access == catalog::Access::Parameter ? QStringLiteral("Parameter")
                             : v->access == catalog::Access::ReadOnly ? QStringLiteral("Variable, read only")
                                                                      : QStringLiteral("Variable");
        QString html = QStringLiteral("<b>%1</b> (%2, %3)<br>%4").arg(str(v->name), kind, typeName(v->type),
                                                                      str(v->description).toHtmlEscaped());
        if (v->type != catalog::ValueType::String)
            html += QStringLiteral("<br><b>Range:</b> %1 to %2 %3 &nbsp; <b>Default:</b> %4%5")
                        .arg(v->minimum)
                        .arg(v->maximum)
                        .arg(str(v->units))
                        .arg(v->defaultValue)
                        .arg(v->chosen ? QStringLiteral(" <i>(chosen: the manual gives none)</i>") : QString());
        return html + QStringLiteral("<br><small>Manual %1</small>").arg(str(v->manualLines));
    }
    return {};
}

QString ServoBasicLanguage::wordAtCursor() const {
    int line = 0, index = 0;
    m_editor.getCursorPosition(&line, &index);
    const QString text = m_editor.text(line);
    int start = qMin(index, int(text.size()));
    if (start > 0 && (start == text.size() || !isWordChar(text[start]))) --start; // just after a word
    if (start < 0 || start >= text.size() || !isWordChar(text[start])) return {};
    while (start > 0 && isWordChar(text[start - 1])) --start;
    int end = start;
    while (end < text.size() && isWordChar(text[end])) ++end;
    return text.mid(start, end - start);
}

QString ServoBasicLanguage::wordBeforeCursor() const {
    int line = 0, index = 0;
    m_editor.getCursorPosition(&line, &index);
    const QString text = m_editor.text(line).left(index);
    if (text.contains(QLatin1Char('\'')) || text.count(QLatin1Char('"')) % 2 == 1) return {}; // comment, string
    int start = int(text.size());
    while (start > 0 && isWordChar(text[start - 1])) --start;
    return text.mid(start);
}

bool ServoBasicLanguage::showCompletions() {
    const QString typed = wordBeforeCursor();
    QStringList matches;
    for (const QString& name : catalogNames())
        if (name.startsWith(typed, Qt::CaseInsensitive) && name.compare(typed, Qt::CaseInsensitive) != 0) matches << name;
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

QString ServoBasicLanguage::showHelpAtCursor() {
    const QString word = wordAtCursor();
    if (word.isEmpty()) {
        hideHelp();
        return {};
    }
    QString html = helpHtml(word);
    if (html.isEmpty())
        html = tr("<b>%1</b> &nbsp;is not a ServoBASIC Plus statement, function or predefined variable.")
                   .arg(word.toHtmlEscaped());
    const long pos = m_editor.SendScintilla(QsciScintilla::SCI_GETCURRENTPOS);
    const int x = int(m_editor.SendScintilla(QsciScintilla::SCI_POINTXFROMPOSITION, 0, pos));
    const int y = int(m_editor.SendScintilla(QsciScintilla::SCI_POINTYFROMPOSITION, 0, pos));
    const int lineHeight = int(m_editor.SendScintilla(QsciScintilla::SCI_TEXTHEIGHT, 0));
    const QPoint below = m_editor.viewport()->mapToGlobal(QPoint(x, y + lineHeight + 2));
    m_help->showHtml(html, below, m_editor.viewport()->mapToGlobal(QPoint(x, y)).y() - 2);
    return word;
}

void ServoBasicLanguage::hideHelp() {
    if (m_help->isVisible()) m_help->hide();
}

bool ServoBasicLanguage::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::ShortcutOverride || event->type() == QEvent::KeyPress) {
        auto* key = static_cast<QKeyEvent*>(event);
        const bool help = key->key() == Qt::Key_F1 && key->modifiers() == Qt::NoModifier;
        const bool complete = key->key() == Qt::Key_Space && key->modifiers() == Qt::ControlModifier;
        if (event->type() == QEvent::ShortcutOverride) {
            if (help || complete) {
                event->accept();
                return true;
            }
        } else if (help) {
            showHelpAtCursor();
            return true;
        } else if (complete) {
            hideHelp();
            showCompletions();
            return true;
        } else {
            hideHelp();
        }
    } else if (event->type() == QEvent::MouseButtonPress || event->type() == QEvent::FocusOut) {
        hideHelp();
    }
    return QObject::eventFilter(watched, event);
}

} // namespace app
