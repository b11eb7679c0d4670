// ProgramEditor: the editor for drive programs (.BDS, .BAS, .MPL). A QsciScintilla with the IDE's look
// (monospace, line numbers, current-line highlight) and file loading/saving that keeps the file's encoding
// and line endings. GUI thread only.
#pragma once

#include <Qsci/qsciscintilla.h>

#include <QString>

class QsciLexer;

namespace editor {

// The outcome of a file operation. message is for the user ("Cannot open ...: permission denied").
struct FileResult {
    bool ok = true;
    QString message;
};

class ProgramEditor final : public QsciScintilla {
    Q_OBJECT
public:
    // How the file's bytes map to text. Drive programs from DOS tools are Latin-1 (code page 437 at best);
    // anything that decodes as valid UTF-8 is taken as UTF-8.
    enum class Encoding { Utf8, Latin1 };

    explicit ProgramEditor(QWidget* parent = nullptr);

    // Installs a language lexer (the editor takes ownership) and gives it the editor's fonts and colours.
    void setLanguageLexer(QsciLexer* lexer);

    // Replaces the text with the file's; on success the editor is unmodified and filePath() is path.
    FileResult loadFile(const QString& path);
    // The file again, as the tab's path says, in place of the text: one undo step, so Edit > Undo brings back
    // what the tab showed (unsaved edits included). Refused like loadFile, the text untouched.
    FileResult reloadFile(const QString& path);
    // Writes the text atomically, in the encoding and line endings it was loaded with (UTF-8 when the
    // text has characters Latin-1 cannot hold). On success the editor is unmodified and filePath() is path.
    FileResult saveFile(const QString& path);
    // Empties the editor for a new, unnamed program.
    void newDocument();
    // Keeps the text but makes it unnamed, so the next save asks for a name (a sample opened from resources).
    void forgetFilePath() { m_filePath.clear(); }

    // SAVE MARKED BLOCK (^K^W): writes the selected text to path, in this file's encoding and line ends.
    FileResult saveSelectedText(const QString& path) const;
    // MERGE FILE (^K^R): inserts the file's text at the cursor as one undo step, its line ends converted
    // to this file's; the cursor ends after it.
    FileResult insertFile(const QString& path);

    QString filePath() const { return m_filePath; }
    Encoding encoding() const { return m_encoding; }

signals:
    // F1 on a word: the catalog topic the language support found there ("MA", "VMAX", "X12", "ERR 25",
    // "$" for labels); emitted by Bds5Language. A help browser may show the topic in full.
    void helpRequested(const QString& topic);

private:
    void updateLineNumberMargin();

    QString m_filePath;
    Encoding m_encoding = Encoding::Utf8;
    int m_marginDigits = 0;
};

} // namespace editor
