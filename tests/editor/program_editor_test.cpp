// ProgramEditor and Bds5Lexer: the colours a BDS5 line gets, and files that come back byte for byte.
#include "editor/bds5_lexer.h"
#include "editor/program_editor.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using editor::Bds5Lexer;
using editor::ProgramEditor;

namespace {
// One letter per byte: d default, c comment, s string, l label, n number.
QByteArray styleCodes(const QByteArray& line) {
    QByteArray codes;
    for (const char style : Bds5Lexer::styleLine(line))
        codes += "dcsln"[int(style)];
    return codes;
}

QByteArray readAll(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

bool writeAll(const QString& path, const QByteArray& bytes) {
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}
} // namespace

class ProgramEditorTest : public QObject {
    Q_OBJECT
private slots:
    void lexerColoursLabelsStringsNumbersAndComments() {
        QCOMPARE(styleCodes("10$ ;START"), QByteArray("llldcccccc"));
        QCOMPARE(styleCodes("POWER-UP$"), QByteArray("lllllllll"));
        QCOMPARE(styleCodes("P \"A;B\""), QByteArray("ddsssss"));
        QCOMPARE(styleCodes("X1 = 1000"), QByteArray("dddddnnnn"));
        QCOMPARE(styleCodes("  ;INDENTED"), QByteArray("ddccccccccc"));
    }
    void lexerNeedsASpaceBeforeAComment() { // `J 10;BAD COMMENT` is not a comment (seed-bds5 §4.1)
        QCOMPARE(styleCodes("J 10;X"), QByteArray("ddnndd"));
    }
    void lexerLeavesAnUnclosedStringAtTheLineEnd() { QCOMPARE(styleCodes("P \"AB"), QByteArray("ddsss")); }

    void latin1FileComesBackByteForByte() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("old.bds"));
        const QByteArray dos = "P \"90\xb0\"\r\nB\r\n"; // Latin-1 degree sign, DOS line ends
        QVERIFY(writeAll(path, dos));
        ProgramEditor ed;
        QVERIFY(ed.loadFile(path).ok);
        QCOMPARE(ed.encoding(), ProgramEditor::Encoding::Latin1);
        QVERIFY(ed.text().contains(QStringLiteral("90\u00b0")));
        const QString copy = dir.filePath(QStringLiteral("copy.bds"));
        QVERIFY(ed.saveFile(copy).ok);
        QCOMPARE(readAll(copy), dos);
        QCOMPARE(ed.filePath(), copy);
        QVERIFY(!ed.isModified());
    }
    void utf8FileStaysUtf8() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("new.bds"));
        const QByteArray bytes = "; \xc2\xb5m\nB\n";
        QVERIFY(writeAll(path, bytes));
        ProgramEditor ed;
        QVERIFY(ed.loadFile(path).ok);
        QCOMPARE(ed.encoding(), ProgramEditor::Encoding::Utf8);
        QVERIFY(ed.saveFile(path).ok);
        QCOMPARE(readAll(path), bytes);
    }
    void missingFileIsReportedNotThrown() {
        ProgramEditor ed;
        ed.setText(QStringLiteral("B"));
        const auto result = ed.loadFile(QStringLiteral("/nonexistent/servodesk/none.bds"));
        QVERIFY(!result.ok);
        QVERIFY2(result.message.contains(QStringLiteral("none.bds")), qPrintable(result.message));
        QCOMPARE(ed.text(), QStringLiteral("B")); // the text on screen is kept
    }
};

QTEST_MAIN(ProgramEditorTest)
#include "program_editor_test.moc"
