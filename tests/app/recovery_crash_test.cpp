// Nothing typed is lost: a ServoDesk process (recovery_victim: the real MainWindow and autosave) gets text
// typed into a file, is killed with SIGKILL once its autosave ran, and a fresh MainWindow then offers the
// text in its recovery bar, restores it into a tab under the file's path, and forgets it on save.
//
// Why this shape: the recovery file must come from the real app code, the death must be a real SIGKILL
// (no destructors, no clean-up), and the restore must be a fresh start. Typing needs key events, which
// only an in-process QTest can deliver without a test-only back door in the servodesk executable — so the
// victim is a small program around the same MainWindow, and the fresh start happens in this process.
#include "app/editing/document_controller.h"
#include "app/editing/editor_area.h"
#include "app/editing/editor_tabs.h"
#include "app/main_window.h"
#include "app/editing/recovery_bar.h"
#include "app/editing/recovery_store.h"

#include "editor/program_editor.h"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QLabel>
#include <QProcess>
#include <QPushButton>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

namespace {
constexpr int kVictimTimeoutMs = 30000;
const QByteArray kOriginal = "10$\nJ 100\n";
const QString kTyped = QStringLiteral("X1 = 4096 ;TYPED BEFORE THE CRASH");

QByteArray readAll(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// Recovery (.json) files under root.
QStringList recoveryFiles(const QString& root) {
    QStringList files;
    QDirIterator it(root, {QStringLiteral("*.json")}, QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext()) files << it.next();
    return files;
}
} // namespace

class RecoveryCrashTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskRecoveryTest"));
    }

    void init() {
        QVERIFY(m_dir.isValid());
        m_recovery = m_dir.filePath(QStringLiteral("recovery"));
        m_file = m_dir.filePath(QStringLiteral("MOTION.BDS"));
        QFile file(m_file);
        QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
        file.write(kOriginal);
        file.close();
        QDir(m_recovery).removeRecursively();
        qputenv("SERVODESK_RECOVERY_DIR", m_recovery.toUtf8());
    }

    void textTypedBeforeSigkillIsRestored() {
        killVictimAfterAutosave();
        QCOMPARE(readAll(m_file), kOriginal); // the file itself never saw the typing
        QCOMPARE(recoveryFiles(m_recovery).size(), 1);
        QVERIFY(QString::fromUtf8(readAll(recoveryFiles(m_recovery).first())).contains(kTyped));

        app::MainWindow window;
        window.show();
        app::RecoveryBar* bar = window.editorArea()->recoveryBar();
        QVERIFY(bar->isVisible());
        QVERIFY2(bar->message().contains(QStringLiteral("MOTION.BDS")), qPrintable(bar->message()));
        QVERIFY(bar->message().contains(QStringLiteral("did not close normally")));
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.grab().save(QCoreApplication::applicationDirPath() + QStringLiteral("/recovery-bar.png"));

        const int tabsBefore = window.editorArea()->tabs()->count();
        QTest::mouseClick(bar->restoreButton(), Qt::LeftButton);
        QVERIFY(!bar->isVisible());
        QCOMPARE(window.editorArea()->tabs()->count(), tabsBefore + 1);
        editor::ProgramEditor* restored = window.editor();
        QCOMPARE(restored->filePath(), m_file);
        QCOMPARE(restored->text(), QString::fromUtf8(kOriginal) + kTyped);
        QVERIFY(restored->isModified());
        QCOMPARE(window.editorArea()->tabs()->tabText(window.editorArea()->tabs()->currentIndex()),
                 QStringLiteral("MOTION.BDS*"));
        QVERIFY(app::RecoveryStore(m_recovery).orphans().isEmpty()); // the dead session is forgotten
        QCOMPARE(recoveryFiles(m_recovery).size(), 1);               // now kept safe by this session

        window.editorArea()->documents()->save(); // a clean save: the recovery file goes
        QCOMPARE(readAll(m_file), kOriginal + kTyped.toUtf8());
        QVERIFY(recoveryFiles(m_recovery).isEmpty());
    }

    void discardForgetsTheText() {
        killVictimAfterAutosave();
        app::MainWindow window;
        app::RecoveryBar* bar = window.editorArea()->recoveryBar();
        QVERIFY(!bar->isHidden());
        QTest::mouseClick(bar->discardButton(), Qt::LeftButton);
        QVERIFY(bar->isHidden());
        QVERIFY(recoveryFiles(m_recovery).isEmpty());
        app::MainWindow next; // and the next start offers nothing
        QVERIFY(next.editorArea()->recoveryBar()->isHidden());
    }

    void cleanExitLeavesNothingToRecover() {
        {
            app::MainWindow window;
            QVERIFY(window.editorArea()->documents()->openFile(m_file));
            window.editor()->append(QStringLiteral("B\n"));
            QTRY_VERIFY_WITH_TIMEOUT(recoveryFiles(m_recovery).size() == 1, 10000);
        } // destroyed without a crash, as after "Discard" on quitting
        QVERIFY(recoveryFiles(m_recovery).isEmpty());
        app::MainWindow next;
        QVERIFY(next.editorArea()->recoveryBar()->isHidden());
    }

private:
    void killVictimAfterAutosave() {
        QProcess victim;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("SERVODESK_RECOVERY_DIR"), m_recovery);
        env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
        victim.setProcessEnvironment(env);
        victim.setProcessChannelMode(QProcess::ForwardedErrorChannel);
        victim.start(QStringLiteral(RECOVERY_VICTIM), {m_file, kTyped});
        QVERIFY(victim.waitForStarted());
        QByteArray output;
        QTRY_VERIFY_WITH_TIMEOUT((output += victim.readAllStandardOutput()).contains("AUTOSAVED"), kVictimTimeoutMs);
        QCOMPARE(victim.state(), QProcess::Running);
        victim.kill(); // SIGKILL: no destructors, no clean-up
        QVERIFY(victim.waitForFinished());
        QCOMPARE(victim.exitStatus(), QProcess::CrashExit);
    }

    QTemporaryDir m_dir;
    QString m_recovery;
    QString m_file;
};

QTEST_MAIN(RecoveryCrashTest)
#include "recovery_crash_test.moc"
