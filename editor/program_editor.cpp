// ProgramEditor: appearance and file handling.
#include "program_editor.h"

#include <Qsci/qscilexer.h>

#include <QFile>
#include <QFileInfo>
#include <QFontDatabase>
#include <QSaveFile>
#include <QStringDecoder>

namespace editor {

namespace {
constexpr int kLineNumberMargin = 0;
constexpr int kFontPointSize = 11;

QFont editorFont() {
    QFont font = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    font.setPointSize(kFontPointSize);
    font.setStyleHint(QFont::Monospace);
    return font;
}

bool fitsLatin1(const QString& text) {
    for (const QChar c : text)
        if (c.unicode() > 0xff) return false;
    return true;
}
} // namespace

ProgramEditor::ProgramEditor(QWidget* parent) : QsciScintilla(parent) {
    setUtf8(true);
    const QFont font = editorFont();
    setFont(font);
    setMarginsFont(font);
    setMarginType(kLineNumberMargin, QsciScintilla::NumberMargin);
    setMarginLineNumbers(kLineNumberMargin, true);
    setMarginsBackgroundColor(QColor(0xf0, 0xf0, 0xf0));
    setMarginsForegroundColor(QColor(0x80, 0x80, 0x80));
    setMarginWidth(1, 6); // a little air between the numbers and the text
    setCaretLineVisible(true);
    SendScintilla(SCI_SETCARETLINEVISIBLEALWAYS, 1); // keep the highlight while the terminal has focus
    setCaretLineBackgroundColor(QColor(0xe8, 0xf2, 0xfe));
    setCaretWidth(2);
    setIndentationsUseTabs(false);
    setTabWidth(4);
    setAutoIndent(true);
    setBraceMatching(QsciScintilla::NoBraceMatch);
    setWrapMode(QsciScintilla::WrapNone);
    // Scintilla's fixed 2000-pixel scroll width shows a horizontal scroll bar on short programs; track
    // the longest line instead.
    SendScintilla(SCI_SETSCROLLWIDTH, 1);
    SendScintilla(SCI_SETSCROLLWIDTHTRACKING, 1);
    setEolMode(QsciScintilla::EolUnix);
    connect(this, &QsciScintilla::linesChanged, this, &ProgramEditor::updateLineNumberMargin);
    updateLineNumberMargin();
}

void ProgramEditor::setLanguageLexer(QsciLexer* lexer) {
    lexer->setParent(this);
    lexer->setDefaultFont(font());
    lexer->setFont(font(), -1);
    lexer->setDefaultPaper(Qt::white);
    lexer->setPaper(Qt::white, -1);
    setLexer(lexer);
    // A lexer resets the margins' font and colours to its own; put the editor's back.
    setMarginsFont(font());
    setMarginsBackgroundColor(QColor(0xf0, 0xf0, 0xf0));
    setMarginsForegroundColor(QColor(0x80, 0x80, 0x80));
    m_marginDigits = 0;
    updateLineNumberMargin();
}

FileResult ProgramEditor::loadFile(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {false, tr("Cannot open %1: %2").arg(QFileInfo(path).fileName(), file.errorString())};
    const QByteArray bytes = file.readAll();
    if (file.error() != QFileDevice::NoError)
        return {false, tr("Cannot read %1: %2").arg(QFileInfo(path).fileName(), file.errorString())};

    QStringDecoder utf8(QStringDecoder::Utf8, QStringDecoder::Flag::Stateless);
    QString text = utf8.decode(bytes);
    m_encoding = Encoding::Utf8;
    if (utf8.hasError()) {
        text = QString::fromLatin1(bytes);
        m_encoding = Encoding::Latin1;
    }
    if (text.startsWith(QChar(0xfeff))) text.remove(0, 1); // a UTF-8 byte-order mark is not program text
    setEolMode(bytes.contains("\r\n") ? QsciScintilla::EolWindows : QsciScintilla::EolUnix);
    setText(text);
    setModified(false);
    m_filePath = path;
    return {};
}

FileResult ProgramEditor::saveFile(const QString& path) {
    // Write the line endings the file had, even where a paste brought in others.
    convertEols(eolMode());
    const QString content = text();
    const bool latin1 = m_encoding == Encoding::Latin1 && fitsLatin1(content);
    const QByteArray bytes = latin1 ? content.toLatin1() : content.toUtf8();

    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return {false, tr("Cannot write %1: %2").arg(QFileInfo(path).fileName(), file.errorString())};
    file.write(bytes);
    if (!file.commit())
        return {false, tr("Cannot save %1: %2").arg(QFileInfo(path).fileName(), file.errorString())};
    m_encoding = latin1 ? Encoding::Latin1 : Encoding::Utf8;
    setModified(false);
    m_filePath = path;
    return {};
}

void ProgramEditor::newDocument() {
    clear();
    setModified(false);
    m_filePath.clear();
    m_encoding = Encoding::Utf8;
    setEolMode(QsciScintilla::EolUnix);
}

FileResult ProgramEditor::saveSelectedText(const QString& path) const {
    QString content = selectedText();
    if (content.isEmpty()) return {false, tr("No block is marked: select text first")};
    content.replace(QStringLiteral("\r\n"), QStringLiteral("\n"));
    if (eolMode() == QsciScintilla::EolWindows) content.replace(QLatin1Char('\n'), QStringLiteral("\r\n"));
    const bool latin1 = m_encoding == Encoding::Latin1 && fitsLatin1(content);
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return {false, tr("Cannot write %1: %2").arg(QFileInfo(path).fileName(), file.errorString())};
    file.write(latin1 ? content.toLatin1() : content.toUtf8());
    if (!file.commit())
        return {false, tr("Cannot save %1: %2").arg(QFileInfo(path).fileName(), file.errorString())};
    return {};
}

FileResult ProgramEditor::insertFile(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {false, tr("Cannot open %1: %2").arg(QFileInfo(path).fileName(), file.errorString())};
    const QByteArray bytes = file.readAll();
    QStringDecoder utf8(QStringDecoder::Utf8, QStringDecoder::Flag::Stateless);
    QString text = utf8.decode(bytes);
    if (utf8.hasError()) text = QString::fromLatin1(bytes);
    if (text.startsWith(QChar(0xfeff))) text.remove(0, 1);
    text.replace(QStringLiteral("\r\n"), QStringLiteral("\n"));
    if (eolMode() == QsciScintilla::EolWindows) text.replace(QLatin1Char('\n'), QStringLiteral("\r\n"));
    const QByteArray inserted = text.toUtf8();
    beginUndoAction();
    const long at = SendScintilla(SCI_GETCURRENTPOS);
    SendScintilla(SCI_INSERTTEXT, at, inserted.constData());
    SendScintilla(SCI_GOTOPOS, static_cast<unsigned long>(at + inserted.size()));
    endUndoAction();
    return {};
}

void ProgramEditor::updateLineNumberMargin() {
    const int digits = qMax(3, int(QString::number(lines()).size()));
    if (digits == m_marginDigits) return;
    m_marginDigits = digits;
    setMarginWidth(kLineNumberMargin, QString(digits + 1, QLatin1Char('9')));
}

} // namespace editor
