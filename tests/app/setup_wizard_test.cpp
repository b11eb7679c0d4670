// The setup wizard (issue 7) against the simulated BDS5: every parameter page reads its variables from
// the drive, an edit on each page is held (nothing sent) until Send Variables, then reaches the drive and
// reads back; the changes save as .VAR; the output test toggles an output at once.
#include "app/drive/drive_connection.h"
#include "app/main_window.h"
#include "app/variables/variable_model.h"
#include "app/wizard/bench_page.h"
#include "app/wizard/parameter_page.h"
#include "app/wizard/setup_wizard.h"
#include "app/wizard/summary_page.h"
#include "app/wizard/wizard_changes.h"

#include "drive_core/catalog/bds5_catalog.h"
#include "serialport/bds5_session.h"

#include <QFile>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>

using app::MainWindow;

namespace {
constexpr int kDriveTimeoutMs = 15000;
// Not touched by the round trip: they would cut the line to the drive or its prompts.
const QStringList kRisky{"BAUD", "ADDR", "WATCH", "PROMPT", "ECHO", "MULTI", "FAULT"};

bool ready(const MainWindow& window) {
    const auto* session = window.connection().session();
    return session && session->state() == serialport::Bds5Session::State::Ready;
}

bool writable(const QString& name) {
    const QByteArray n = name.toLatin1();
    const auto ref = drive_core::catalog::bds5::findVariable(std::string_view(n.constData(), std::size_t(n.size())));
    using W = drive_core::catalog::bds5::WriteCondition;
    return ref && ref->info->write != W::Never && ref->info->write != W::Factory;
}

bool isSwitch(const QString& name) {
    const QByteArray n = name.toLatin1();
    return drive_core::catalog::bds5::findVariable(std::string_view(n.constData(), std::size_t(n.size())))
        ->info->isSwitch;
}
} // namespace

class SetupWizardTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskSetupWizardTest"));
        QSettings().clear();
    }

    void eachPageRoundTripsItsVariables() {
        MainWindow window;
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
        QTRY_VERIFY_WITH_TIMEOUT(ready(window), kDriveTimeoutMs);
        app::SetupWizard wizard(window.connection(), &window);
        wizard.show();
        QCOMPARE(wizard.pageIds().size(), 7 + 6 + 2); // bench pages, parameter pages, reset, send
        QSignalSpy sent(&window.connection(), &app::DriveConnection::rawSent);
        QHash<QString, QString> chosen;
        for (app::ParameterPage* page : wizard.parameterPages()) {
            while (wizard.currentPage() != page) wizard.next();
            // Read: every readable variable of the page shows the drive's value.
            QTRY_VERIFY_WITH_TIMEOUT(std::all_of(page->names().cbegin(), page->names().cend(),
                                                 [&](const QString& n) {
                                                     return !wizard.model().isReadable(n) ||
                                                            !wizard.model().value(n).isEmpty();
                                                 }),
                                     kDriveTimeoutMs);
            QString name;
            for (const QString& n : page->names())
                if (writable(n) && !kRisky.contains(n) && !wizard.model().value(n).isEmpty() && !chosen.contains(n)) {
                    name = n;
                    break;
                }
            QVERIFY2(!name.isEmpty(), qPrintable(page->title()));
            const QString value = wizard.model().value(name);
            if (!isSwitch(name)) QCOMPARE(page->text(name), value);
            const QString next = isSwitch(name)
                                     ? (value == QLatin1String("0") ? QStringLiteral("1") : QStringLiteral("0"))
                                     : QString::number(value.toLongLong() + 1);
            page->setText(name, next);
            QVERIFY2(wizard.changes().changedNames().contains(name), qPrintable(name + ' ' + next));
            chosen.insert(name, next);
        }
        QTest::qWait(200);
        for (const QList<QVariant>& bytes : sent) // reads only: nothing assigned before Send
            QVERIFY2(bytes.first().toByteArray().startsWith("P ") || bytes.first().toByteArray() == "\r",
                     bytes.first().toByteArray().constData());

        while (wizard.currentPage() != wizard.summaryPage()) wizard.next();
        QCOMPARE(wizard.summaryPage()->table()->topLevelItemCount(), chosen.size());
        QTemporaryDir dir;
        const QString var = dir.filePath(QStringLiteral("SETUP.VAR"));
        QVERIFY(wizard.summaryPage()->saveVar(var));
        QFile file(var);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QString saved = QString::fromLatin1(file.readAll());
        for (auto it = chosen.cbegin(); it != chosen.cend(); ++it)
            QVERIFY2(saved.contains(it.key() + ' ' + it.value() + '\n'), qPrintable(saved));

        QTest::mouseClick(wizard.summaryPage()->sendButton(), Qt::LeftButton);
        for (auto it = chosen.cbegin(); it != chosen.cend(); ++it) {
            QTRY_COMPARE_WITH_TIMEOUT(wizard.summaryPage()->statusOf(it.key()), QStringLiteral("sent"),
                                      kDriveTimeoutMs);
            QTRY_COMPARE_WITH_TIMEOUT(wizard.model().value(it.key()), it.value(), kDriveTimeoutMs); // read back
        }
        QVERIFY(wizard.changes().changedNames().isEmpty());
    }

    void theOutputTestSwitchesAnOutputAtOnce() {
        MainWindow window;
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
        QTRY_VERIFY_WITH_TIMEOUT(ready(window), kDriveTimeoutMs);
        app::SetupWizard wizard(window.connection(), &window);
        wizard.show();
        app::BenchPage* outputs = wizard.benchPages().last();
        QCOMPARE(outputs->title(), QStringLiteral("Output Test"));
        while (wizard.currentPage() != outputs) wizard.next();
        QTest::mouseClick(outputs->toggleFor(QStringLiteral("O2")), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(outputs->log().contains(QStringLiteral("--> O2 1")), kDriveTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(wizard.model().value(QStringLiteral("O2")), QStringLiteral("1"), kDriveTimeoutMs);
    }
};

QTEST_MAIN(SetupWizardTest)
#include "setup_wizard_test.moc"
