// One progress window for every family's transfers (issue 17): the SC750's source file and its Run Program
// download, and the PMC-960's Download Program show the same TransferDialog as the BDS5's (program_transfer
// test): a bar that counts, gone when the drive holds the program, and after Cancel the word "Cancelled"
// with what the drive now holds, until the user closes it.
#include "family_window.h"

#include "app/main_window.h"
#include "app/transfer/transfer_dialog.h"
#include "families/pmc960/pmc960_program_transfer.h"
#include "families/pmc960/pmc960_workspace.h"
#include "families/sc750/sc750_controller_menu.h"
#include "families/sc750/sc750_debugger.h"
#include "families/sc750/sc750_workspace.h"

#include "editor_tabs.h"
#include "editor_area.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QFile>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>

#include <functional>

using app::MainWindow;
using app::TransferDialog;

namespace {
constexpr int kTimeoutMs = 20000;

QString example(const char* name) {
    return family_window::sc750Example(name);
}

// A 60-line MPL routine: long enough to be caught part way.
QString longMpl() {
    QString program = QStringLiteral("@A\n");
    for (int i = 1; i <= 60; ++i) program += QStringLiteral("A%1\n").arg(i * 10);
    return program;
}

// Connects the family's simulated drive with a program in a tab and returns what starts its download.
std::function<void()> prepare(MainWindow& window, const QString& which) {
    if (which.startsWith(QLatin1String("pmc960"))) {
        app::Pmc960Workspace& ws = family_window::connectPmc960(window);
        if (!QTest::qWaitFor([&] { return ws.isConnected(); }, kTimeoutMs)) return {};
        window.editorArea()->tabs()->addEditor(QStringLiteral("long.mpl"))->setText(longMpl());
        return [&ws] { ws.action(QStringLiteral("Download Program"))->trigger(); };
    }
    // Longer than a few of the SC750's 64-byte chunks.
    const QString program = example("02-loop-again.bas") + QStringLiteral("' comment\n").repeated(40);
    app::Sc750Workspace& ws = family_window::connectSc750WithProgram(window, program);
    if (!QTest::qWaitFor([&] { return ws.isConnected(); }, kTimeoutMs)) return {};
    if (which == QLatin1String("sc750-run"))
        return [&ws] { ws.action(QStringLiteral("Run Program"))->trigger(); };
    return [&ws] { qobject_cast<app::Sc750ControllerMenu*>(ws.menus().at(1))->downloadSource(); };
}
// The download started as the user starts it, and the progress window it opened (nullptr when none).
TransferDialog* startTransfer(MainWindow& window, const QString& which) {
    const auto start = prepare(window, which);
    if (!start) return nullptr;
    start();
    return TransferDialog::active();
}
} // namespace

class TransferDialogFamiliesTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void theProgressWindowCountsAndGoesWhenTheDriveHoldsTheProgram_data() {
        QTest::addColumn<QString>("which");
        QTest::addColumn<QString>("title");
        QTest::newRow("SC750 source file") << QStringLiteral("sc750-source") << QStringLiteral("Download Source File");
        QTest::newRow("SC750 Run Program") << QStringLiteral("sc750-run") << QStringLiteral("Run Program");
        QTest::newRow("PMC-960") << QStringLiteral("pmc960") << QStringLiteral("Download Program");
    }
    void theProgressWindowCountsAndGoesWhenTheDriveHoldsTheProgram() {
        QFETCH(QString, which);
        QFETCH(QString, title);
        MainWindow window;
        window.show();
        QPointer<TransferDialog> dialog = startTransfer(window, which);
        QVERIFY(dialog);
        QCOMPARE(dialog->windowTitle(), title);
        QVERIFY(dialog->isVisible());
        auto* bar = dialog->findChild<QProgressBar*>();
        QVERIFY(bar);
        QSignalSpy counted(bar, &QProgressBar::valueChanged);
        QTRY_VERIFY_WITH_TIMEOUT(!dialog, kTimeoutMs); // closed (and deleted) once the drive holds it
        QVERIFY(!TransferDialog::active());
        // The bar counted up, chunk by chunk or line by line, before it went.
        QVERIFY2(counted.count() >= 2, qPrintable(QString::number(counted.count())));
        QVERIFY(counted.last().at(0).toInt() > counted.first().at(0).toInt());
    }

    void cancelSaysWhatTheDriveHolds_data() {
        QTest::addColumn<QString>("which");
        QTest::addColumn<QString>("result");
        QTest::newRow("SC750 source file") << QStringLiteral("sc750-source")
                                           << QStringLiteral("cancelled; the controller keeps its old source");
        QTest::newRow("PMC-960") << QStringLiteral("pmc960") << QStringLiteral("Download cancelled after");
    }
    void cancelSaysWhatTheDriveHolds() {
        QFETCH(QString, which);
        QFETCH(QString, result);
        MainWindow window;
        window.show();
        QPointer<TransferDialog> dialog = startTransfer(window, which);
        QVERIFY(dialog);
        auto* buttons = dialog->findChild<QDialogButtonBox*>();
        QVERIFY(buttons);
        QPushButton* cancel = buttons->button(QDialogButtonBox::Cancel);
        QVERIFY(cancel && cancel->isEnabled());
        cancel->click();
        QVERIFY(!cancel->isEnabled()); // asked once; the drive answers before the dialog says more
        QTRY_VERIFY_WITH_TIMEOUT(dialog && dialog->isFinished(), kTimeoutMs);
        QVERIFY(dialog->isVisible()); // stays with the result until closed
        QCOMPARE(dialog->stageText(), QStringLiteral("Cancelled"));
        QVERIFY2(dialog->resultText().contains(result), qPrintable(dialog->resultText()));
        QVERIFY(!TransferDialog::active());
        dialog->reject(); // Close
        QTRY_VERIFY_WITH_TIMEOUT(!dialog, kTimeoutMs);
    }
};

QTEST_MAIN(TransferDialogFamiliesTest)
#include "transfer_dialog_families_test.moc"
