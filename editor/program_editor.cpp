// ProgramEditor: appearance and file handling.
#include "program_editor.h"

#include <Qsci/qscilexer.h>

#include <QFile>
#include <QFileInfo>
#include <QFontDatabase>
#include <QSaveFile>
#include <QStringDecoder>

#include <utility>

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

// chosen: the largest program file the editor opens. A BDS5 holds 32 K of program text, an SC750 a few
// hundred K of source; 1 MiB leaves room for comments, and a larger file is not a drive program.
constexpr qint64 kMaxProgramBytes = 1 << 20;

struct ProgramText {
    FileResult result;
    QString text;
    ProgramEditor::Encoding encoding = ProgramEditor::Encoding::Utf8;
    bool crlf = false;
};

// A drive program's text, or why the file is not one. A binary file (a NUL byte) or an oversized one is
// refused whole rather than shown in part, so that saving can never write back less than the file held.
ProgramText readProgramText(const QString& path) {
    ProgramText read;
    const QString name = QFileInfo(path).fileName();
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        read.result = {false, ProgramEditor::tr("Cannot open %1: %2").arg(name, file.errorString())};
        return read;
    }
    if (file.size() > kMaxProgramBytes) {
        read.result = {false, ProgramEditor::tr("%1 is %L2 bytes, more than any drive program (at most %L3): it "
                                                "was not opened.")
                                  .arg(name)
                                  .arg(file.size())
                                  .arg(kMaxProgramBytes)};
        return read;
    }
    const QByteArray bytes = file.readAll();
    if (file.error() != QFileDevice::NoError) {
        read.result = {false, ProgramEditor::tr("Cannot read %1: %2").arg(name, file.errorString())};
        return read;
    }
    if (const qsizetype nul = bytes.indexOf('\0'); nul >= 0) {
        read.result = {false, ProgramEditor::tr("%1 is not a text file (a NUL byte at offset %L2 of %L3): it was "
                                                "not opened.")
                                  .arg(name)
                                  .arg(nul)
                                  .arg(bytes.size())};
        return read;
    }
    QStringDecoder utf8(QStringDecoder::Utf8, QStringDecoder::Flag::Stateless);
    read.text = utf8.decode(bytes);
    if (utf8.hasError()) {
        read.text = QString::fromLatin1(bytes);
        read.encoding = ProgramEditor::Encoding::Latin1;
    }
    if (read.text.startsWith(QChar(0xfeff))) read.text.remove(0, 1); // a UTF-8 byte-order mark is not text
    read.crlf = bytes.contains("\r\n");
    return read;
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
    ProgramText read = readProgramText(path);
    if (!read.result.ok) return read.result;
    m_encoding = read.encoding;
    setEolMode(read.crlf ? QsciScintilla::EolWindows : QsciScintilla::EolUnix);
    setText(read.text);
    setModified(false);
    m_filePath = path;
    return {};
}

FileResult ProgramEditor::reloadFile(const QString& path) {
    ProgramText read = readProgramText(path);
    if (!read.result.ok) return read.result;
    m_encoding = read.encoding;
    setEolMode(read.crlf ? QsciScintilla::EolWindows : QsciScintilla::EolUnix);
    beginUndoAction();
    selectAll();
    replaceSelectedText(read.text);
    endUndoAction();
    setModified(false); // the save point: undo marks the tab modified again
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
    ProgramText read = readProgramText(path);
    if (!read.result.ok) return read.result;
    QString text = std::move(read.text);
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
