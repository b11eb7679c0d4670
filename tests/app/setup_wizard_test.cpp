// The setup wizard (issue 7) against the simulated BDS5: every parameter page reads its variables from
// the drive, an edit on each page is held (nothing sent) until Send Variables, then reaches the drive and
// reads back; the changes save as .VAR; the output test toggles an output at once; the Communicate and Drive
// Feedback readouts show the drive's answers, the units page previews the conversion as a user types, and the
// Motor Setup page swaps the simulated motor (its ICONT read anew, the I/O panel showing the same motor). Every
// page shows "Step N of M" in the same header.
#include "app_test_support.h"
#include "families/bds5/drive_connection.h"
#include "families/bds5/io_panel.h"
#include "app/main_window.h"
#include "app/variables/variable_model.h"
#include "families/bds5/wizard/bench_page.h"
#include "families/bds5/wizard/motor_choice.h"
#include "families/bds5/wizard/parameter_page.h"
#include "families/bds5/wizard/setup_wizard.h"
#include "families/bds5/wizard/summary_page.h"
#include "families/bds5/wizard/wizard_changes.h"

#include "drive_core/bds5/bds5_drive.h"
#include "drive_core/catalog/bds5_catalog.h"
#include "drive_core/physics/motor_parameters.h"
#include "serialport/bds5_session.h"

#include <QComboBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>

using app::MainWindow;

namespace {
using app_test::kDriveTimeoutMs;
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

// One more than `value`, unless the manual caps the variable at another's present value (VOSPD at most
// 1.2 VMAX, ACC at most AMAX, L2048, L2186) and one more would pass it: then one less.
QString nextValue(const QString& name, const QString& value, const app::VariableModel& model) {
    const QByteArray n = name.toLatin1();
    const auto ref = drive_core::catalog::bds5::findVariable(std::string_view(n.constData(), std::size_t(n.size())));
    const qint64 up = value.toLongLong() + 1;
    if (ref && !ref->info->maximumVariable.empty()) {
        const QString limit = QString::fromLatin1(ref->info->maximumVariable.data(),
                                                  qsizetype(ref->info->maximumVariable.size()));
        if (double(up) > model.value(limit).toDouble() * double(ref->info->maximumPercent) / 100.0)
            return QString::number(up - 2);
    }
    return QString::number(up);
}

// The wizard's own label (not one of the page's) that shows text, if one is visible.
const QLabel* wizardLabel(const QWizard& wizard, const QString& text) {
    for (const QLabel* label : wizard.findChildren<QLabel*>())
        if (label->isVisible() && label->text() == text && !wizard.currentPage()->isAncestorOf(label)) return label;
    return nullptr;
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
            // Issue 19, item 11: AMAX's field showed "00000" of 3000000. Every value is whole in its field.
            for (const QLineEdit* field : page->findChildren<QLineEdit*>()) {
                if (field->text().isEmpty()) continue;
                const int needed = field->fontMetrics().horizontalAdvance(field->text());
                QTRY_VERIFY2(field->contentsRect().width() > needed,
                             qPrintable(QStringLiteral("%1: %2 px for %3 px").arg(field->text()).arg(
                                 field->contentsRect().width()).arg(needed)));
            }
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
                                     : nextValue(name, value, wizard.model());
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

    // Issue 19: every page says where it is, "Step N of M", in the one header QWizard draws for a page with a
    // subtitle. (The bench pages had none, and QWizard showed their titles in the page body, in another style.)
    void everyPageSaysItsStepUnderOneHeader() {
        app::DriveConnection connection; // not connected: only the pages' headers are looked at
        app::SetupWizard wizard(connection);
        wizard.show();
        const QList<int> ids = wizard.pageIds();
        const QWidget* header = nullptr;
        for (qsizetype i = 0; i < ids.size(); ++i) {
            while (wizard.currentId() != ids[i]) wizard.next();
            const QWizardPage* page = wizard.currentPage();
            const QString step = QStringLiteral("Step %1 of %2").arg(i + 1).arg(ids.size());
            QVERIFY2(page->subTitle().startsWith(step), qPrintable(page->title() + ": " + page->subTitle()));
            const QLabel* title = wizardLabel(wizard, page->title());
            const QLabel* subTitle = wizardLabel(wizard, page->subTitle());
            QVERIFY2(title && subTitle, qPrintable(page->title()));
            if (!header) header = title->parentWidget();
            QVERIFY2(title->parentWidget() == header && subTitle->parentWidget() == header, qPrintable(page->title()));
        }
        QCOMPARE(wizard.currentPage(), wizard.summaryPage());
        QVERIFY(wizard.summaryPage()->subTitle().startsWith(QStringLiteral("Step 15 of 15 \u2014 ")));
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

    void communicateAndFeedbackShowTheDrivesAnswers() {
        MainWindow window;
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
        QTRY_VERIFY_WITH_TIMEOUT(ready(window), kDriveTimeoutMs);
        app::SetupWizard wizard(window.connection(), &window);
        wizard.show();
        app::BenchPage* communicate = wizard.benchPages().first();
        QCOMPARE(communicate->title(), QStringLiteral("Communicate with the BDS5"));
        QTest::mouseClick(communicate->actionButton(QStringLiteral("Test")), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(communicate->log().contains(QStringLiteral("--> P BAUD ADDR")), kDriveTimeoutMs);
        // The simulated drive's UART runs at 9600 baud, address 0 (power-up values).
        QTRY_COMPARE_WITH_TIMEOUT(communicate->readoutText(QStringLiteral("BAUD")), QStringLiteral("BAUD  9600"),
                                  kDriveTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(communicate->readoutText(QStringLiteral("ADDR")), QStringLiteral("ADDR  0"),
                                  kDriveTimeoutMs);

        // Drive Feedback while the motor jogs at 100 RPM: VFB shows about 100 and PFB keeps counting.
        window.connection().sendCommand(QStringLiteral("PLIM=0"));
        window.connection().sendCommand(QStringLiteral("EN"));
        window.connection().sendCommand(QStringLiteral("J 100"));
        app::BenchPage* feedback = nullptr;
        for (app::BenchPage* page : wizard.benchPages())
            if (page->title() == QStringLiteral("Drive Feedback")) feedback = page;
        QVERIFY(feedback);
        while (wizard.currentPage() != feedback) wizard.next();
        auto number = [feedback](const char* name) {
            return feedback->readoutText(QString::fromLatin1(name)).section(QStringLiteral("  "), 1).toDouble();
        };
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(number("VFB") - 100) < 5, kDriveTimeoutMs);
        const double pfb = number("PFB");
        // 100 RPM is 6.8 counts a millisecond (4096 a turn): PFB moves on between polls.
        QTRY_VERIFY_WITH_TIMEOUT(number("PFB") > pfb + 500, kDriveTimeoutMs);
        window.connection().sendCommand(QStringLiteral("J 0"));
    }

    void theUnitsPagePreviewsTheConversionAsTyped() {
        MainWindow window;
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
        QTRY_VERIFY_WITH_TIMEOUT(ready(window), kDriveTimeoutMs);
        app::SetupWizard wizard(window.connection(), &window);
        wizard.show();
        app::ParameterPage* units = wizard.parameterPages().first();
        QVERIFY(units->title().contains(QStringLiteral("Units")));
        while (wizard.currentPage() != units) wizard.next();
        // The power-up units: counts, RPM, RPM/s and percent.
        QTRY_VERIFY_WITH_TIMEOUT(units->previewText().contains(QStringLiteral("1 velocity unit = 1 RPM")),
                                 kDriveTimeoutMs);
        QVERIFY2(units->previewText().contains(QStringLiteral("1 position unit = 1 counts")),
                 qPrintable(units->previewText()));
        // Revolutions for position (PNUM 4096) and RPS for velocity (VNUM x 60): shown at once, nothing sent.
        units->setText(QStringLiteral("PNUM"), QStringLiteral("4096"));
        units->setText(QStringLiteral("VNUM"), QString::number(44739 * 60));
        QVERIFY2(units->previewText().contains(QStringLiteral("1 position unit = 4096 counts")),
                 qPrintable(units->previewText()));
        QVERIFY2(units->previewText().contains(QStringLiteral("1 velocity unit = 60 RPM")),
                 qPrintable(units->previewText()));
        QCOMPARE(wizard.changes().changedNames().size(), 2);
    }

    void motorSetupSwapsTheSimulatedMotor() {
        MainWindow window;
        window.connectDrive(app::ConnectionChoice::simulator());
        window.show();
        QTRY_VERIFY_WITH_TIMEOUT(ready(window), kDriveTimeoutMs);
        app::SetupWizard wizard(window.connection(), &window);
        wizard.show();
        const int id = wizard.pageIdOf(QStringLiteral("Motor Setup"));
        QVERIFY(id >= 0);
        while (wizard.currentId() != id) wizard.next();
        app::MotorChoice* choice = wizard.motorChoice();
        QVERIFY(choice->isVisible() && choice->isSimulated() && choice->list()->isEnabled());
        QVERIFY(choice->note().startsWith(QStringLiteral("Simulated drive")));
        QTRY_VERIFY_WITH_TIMEOUT(!wizard.model().value(QStringLiteral("ICONT")).isEmpty(), kDriveTimeoutMs);
        const QString before = choice->list()->currentText();
        const QString icontBefore = wizard.model().value(QStringLiteral("ICONT"));

        // Another reference motor: the simulated drive powers up with it (its sign-on on the wire), the page
        // reads its variables again, and the I/O panel's bench shows the same motor.
        QString name;
        for (const auto& m : drive_core::physics::referenceMotors())
            if (QString::fromLatin1(m.name.data(), qsizetype(m.name.size())) != before)
                name = QString::fromLatin1(m.name.data(), qsizetype(m.name.size()));
        QVERIFY(!name.isEmpty());
        QSignalSpy changed(choice, &app::MotorChoice::motorChanged);
        QSignalSpy received(&window.connection(), &app::DriveConnection::rawReceived);
        QSignalSpy sent(&window.connection(), &app::DriveConnection::rawSent);
        const int index = choice->list()->findText(name);
        choice->list()->setCurrentIndex(index);
        emit choice->list()->activated(index); // as a user's pick
        QVERIFY(changed.wait(kDriveTimeoutMs));
        QCOMPARE(changed.first().first().toString(), name);
        const auto allOf = [](const QSignalSpy& spy) {
            QByteArray bytes;
            for (const QList<QVariant>& s : spy) bytes += s.first().toByteArray();
            return bytes;
        };
        QTRY_VERIFY_WITH_TIMEOUT(allOf(received).contains(drive_core::bds5::kSignOn), kDriveTimeoutMs);
        QTRY_VERIFY_WITH_TIMEOUT(allOf(sent).contains("P ICONT"), kDriveTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(wizard.model().value(QStringLiteral("ICONT")), icontBefore, kDriveTimeoutMs);
        // The I/O panel's bench shows the same motor.
        auto* io = window.findChild<app::IoPanel*>();
        QVERIFY(io);
        QComboBox* ioMotor = nullptr;
        for (QComboBox* box : io->findChildren<QComboBox*>())
            if (box->findText(name) >= 0) ioMotor = box;
        QVERIFY(ioMotor);
        QTRY_COMPARE_WITH_TIMEOUT(ioMotor->currentText(), name, kDriveTimeoutMs);
    }
};

QTEST_MAIN(SetupWizardTest)
#include "setup_wizard_test.moc"
