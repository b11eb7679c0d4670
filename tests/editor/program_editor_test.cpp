// ProgramEditor: files that come back byte for byte.
#include "editor/program_editor.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using editor::ProgramEditor;

namespace {
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
    // The BDS5 lexer's colours are tested in bds5_language_test.

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
    // Issue 19, item 7: a binary file was cut at its first NUL byte ("75 of 24,000 bytes") and saving it
    // would have destroyed the rest. A binary or oversized file is refused whole, and the editor keeps its text.
    void binaryAndOversizedFilesAreRefusedNotTruncated() {
        QTemporaryDir dir;
        const QString binary = dir.filePath(QStringLiteral("RANDOM.BDS"));
        QByteArray bytes(4000, 'A');
        bytes[75] = '\0';
        QVERIFY(writeAll(binary, bytes));
        ProgramEditor ed;
        ed.setText(QStringLiteral("B"));
        auto result = ed.loadFile(binary);
        QVERIFY(!result.ok);
        QVERIFY2(result.message.contains(QStringLiteral("RANDOM.BDS")) && result.message.contains(QStringLiteral("75")),
                 qPrintable(result.message));
        QCOMPARE(ed.text(), QStringLiteral("B"));
        QVERIFY(!ed.insertFile(binary).ok); // MERGE FILE refuses it too
        QCOMPARE(ed.text(), QStringLiteral("B"));

        const QString big = dir.filePath(QStringLiteral("BIG.BDS"));
        QVERIFY(writeAll(big, QByteArray(3 * 1024 * 1024, 'P')));
        result = ed.loadFile(big);
        QVERIFY(!result.ok);
        QVERIFY2(result.message.contains(QStringLiteral("BIG.BDS")), qPrintable(result.message));
        QCOMPARE(ed.text(), QStringLiteral("B"));
        QCOMPARE(readAll(big).size(), 3 * 1024 * 1024); // untouched on disk
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
