// Options persist (and the password only when remembered), apply (colours, autobaud, axis wake-up,
// cable disconnect and reconnect), and the help browser shows the catalog's words for VMAX, ERR 25, MA.
#include "app_test_support.h"
#include "app/settings/app_options.h"
#include "families/bds5/drive_connection.h"
#include "app/help/help_browser.h"
#include "app/main_window.h"
#include "app/settings/options_controller.h"
#include "app/settings/options_dialog.h"
#include "app/drive/terminal_widget.h"

#include "drive_core/catalog/bds5_catalog.h"
#include "editor/program_editor.h"

#include <Qsci/qscilexer.h>
#include "serialport/bds5_session.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QLineEdit>
#include <QSettings>
#include <QStandardPaths>
#include <QMenuBar>
#include <QTest>

using app::AppOptions;
using app::MainWindow;
namespace cat = drive_core::catalog::bds5;

namespace {
using app_test::kDriveTimeoutMs;
bool ready(const MainWindow& window) {
    const auto* session = window.connection().session();
    return session && session->state() == serialport::Bds5Session::State::Ready;
}
QString lastLine(const MainWindow& window) {
    return window.terminal()->text().split(QLatin1Char('\n')).last();
}
QString str(std::string_view s) {
    return QString::fromUtf8(s.data(), qsizetype(s.size()));
}
} // namespace

class OptionsHelpTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskOptionsTest"));
    }
    void init() {
        QSettings().clear();
        AppOptions{}.save();
    }

    void optionsPersistAndThePasswordOnlyWhenRemembered() {
        auto* dialog = new app::OptionsDialog;
        dialog->findChild<QComboBox*>(QStringLiteral("optionsBaud"))->setCurrentText(QStringLiteral("19200"));
        dialog->findChild<QCheckBox*>(QStringLiteral("optionsAutobaud"))->setChecked(true);
        auto* axis = dialog->findChild<QComboBox*>(QStringLiteral("optionsAxis"));
        axis->setCurrentIndex(axis->findData(QStringLiteral("B")));
        dialog->findChild<QLineEdit*>(QStringLiteral("optionsPassword"))->setText(QStringLiteral("SECRET"));
        dialog->findChild<QComboBox*>(QStringLiteral("optionsTheme"))->setCurrentIndex(1);
        dialog->findChild<QComboBox*>(QStringLiteral("optionsKeymap"))->setCurrentIndex(1);
        dialog->accept();
        delete dialog;

        QSettings settings;
        QCOMPARE(settings.value(QStringLiteral("connection/baud")).toInt(), 19200);
        QCOMPARE(settings.value(QStringLiteral("editor/keymap")).toString(), QStringLiteral("classic"));
        QVERIFY(!settings.contains(QStringLiteral("options/password"))); // not remembered: not written
        const AppOptions now = AppOptions::current();
        QVERIFY(now.autobaud);
        QCOMPARE(now.axis, QChar(u'B'));
        QCOMPARE(now.drivePassword, QStringLiteral("SECRET")); // but kept for this session
        QCOMPARE(now.theme, AppOptions::Theme::Dark);
        QCOMPARE(now.keymap, AppOptions::Keymap::Classic);

        app::OptionsDialog again; // a new dialog starts from what was stored
        QCOMPARE(again.options(), now);
        QCOMPARE(again.choice().baudRate, 19200);

        AppOptions remembered = now;
        remembered.rememberPassword = true;
        remembered.save();
        QCOMPARE(QSettings().value(QStringLiteral("options/password")).toString(), QStringLiteral("SECRET"));
        remembered.rememberPassword = false; // unticking forgets the stored password
        remembered.save();
        QVERIFY(!QSettings().contains(QStringLiteral("options/password")));
    }

    void darkThemeColoursTerminalAndEditorAndLightPutsThemBack() {
        MainWindow window;
        const QColor editorPaper = window.editor()->lexer()->paper(0);
        AppOptions dark;
        dark.theme = AppOptions::Theme::Dark;
        window.optionsController().apply(dark);
        QVERIFY(window.terminal()->palette().color(QPalette::Base).lightness() < 60);
        QVERIFY(window.editor()->lexer()->paper(0).lightness() < 60);
        QVERIFY(window.editor()->lexer()->color(0).lightness() > 150);
        window.optionsController().apply(AppOptions{});
        QVERIFY(window.terminal()->palette().color(QPalette::Base).lightness() > 200);
        QCOMPARE(window.editor()->lexer()->paper(0), editorPaper);
    }

    void autobaudAndAxisWakeUpAreSentOnConnect() {
        AppOptions options;
        options.autobaud = true;
        options.save();
        MainWindow window;
        QByteArray wire;
        connect(&window.connection(), &app::DriveConnection::rawSent, &window, [&wire](const QByteArray& b) { wire += b; });
        window.connectDrive(app::ConnectionChoice::simulator());
        QTRY_VERIFY_WITH_TIMEOUT(ready(window) && lastLine(window) == QStringLiteral("-->"), kDriveTimeoutMs);
        QVERIFY2(wire.startsWith(QByteArray(AppOptions::kAutobaudReturns, '\r')), wire.constData());

        // Make the drive axis A of a multidrop line: a new ID sleeps until "\A" wakes it (L5449-5451), so the
        // ADDR line is echoed and no prompt follows; then wake axis A up from the options.
        QVERIFY(!window.optionsController().findChild<QAction*>(QStringLiteral("wakeUpAxisAction"))->isEnabled());
        window.connection().sendCommand(QStringLiteral("ADDR 65"));
        QTRY_VERIFY_WITH_TIMEOUT(window.terminal()->text().contains(QStringLiteral("-->ADDR 65")), kDriveTimeoutMs);
        options.axis = u'A';
        options.save();
        window.optionsController().apply(options);
        QAction* wake = window.optionsController().findChild<QAction*>(QStringLiteral("wakeUpAxisAction"));
        QVERIFY(wake->isEnabled());
        const QString before = window.terminal()->text();
        wake->trigger();
        QTRY_VERIFY2_WITH_TIMEOUT(window.terminal()->text().size() > before.size() && lastLine(window) == QStringLiteral("A->"),
                                  qPrintable(window.terminal()->text().right(200)), kDriveTimeoutMs);
        QVERIFY2(wire.endsWith("\\A"), wire.right(40).constData());
    }

    void cableDisconnectThenReconnect() {
        MainWindow window;
        window.connectDrive(app::ConnectionChoice::simulator());
        QTRY_VERIFY_WITH_TIMEOUT(ready(window), kDriveTimeoutMs);
        app::OptionsController& options = window.optionsController();
        QVERIFY(options.cableDisconnectAction()->isEnabled());
        QVERIFY(!options.reconnectAction()->isEnabled());
        window.connection().sendCommand(QStringLiteral("P 1"));
        window.connection().sendCommand(QStringLiteral("P 2")); // still queued: dropped, never sent
        options.cableDisconnectAction()->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(!window.connection().isConnected(), kDriveTimeoutMs);
        QVERIFY(window.terminal()->text().contains(QStringLiteral("[The port is closed")));
        QVERIFY(!window.terminal()->text().contains(QStringLiteral("-->P 2")));
        QVERIFY(options.reconnectAction()->isEnabled());
        options.reconnectAction()->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(ready(window) && lastLine(window) == QStringLiteral("-->"), kDriveTimeoutMs);
    }

    void helpBrowserShowsTheCatalog() {
        app::HelpBrowser help;
        QVERIFY(help.showTopic(QStringLiteral("vmax")));
        QCOMPARE(help.currentKey(), QStringLiteral("VMAX"));
        const auto vmax = cat::findVariable("VMAX");
        QVERIFY(vmax);
        QVERIFY(help.pageText().contains(str(vmax->info->description)));
        QVERIFY(help.pageText().contains(QStringLiteral("Units\tVEL")) || help.pageText().contains(QStringLiteral("VEL")));
        QVERIFY(help.pageText().contains(str(vmax->info->manualLines)));

        QVERIFY(help.showTopic(QStringLiteral("ERR 25")));
        const cat::ErrorInfo* pe = cat::findError(25);
        QVERIFY(help.pageText().contains(QStringLiteral("PE OVERFLOW")));
        QVERIFY(help.pageText().contains(str(pe->meaning)));
        QVERIFY(help.pageText().contains(str(pe->remedy)));

        QVERIFY(help.showTopic(QStringLiteral("MA")));
        const cat::CommandInfo* ma = cat::findCommand("MA");
        QVERIFY(help.pageText().contains(str(ma->longName)));
        QVERIFY(help.pageText().contains(str(ma->syntax)));
        QVERIFY(help.pageText().contains(str(ma->description)));
        QVERIFY(help.pageText().contains(QStringLiteral("interactive (-->)")));

        QVERIFY(help.showTopic(QStringLiteral("X12"))); // an indexed variable: its family
        QCOMPARE(help.currentKey(), QStringLiteral("X"));
        QVERIFY(help.showTopic(QStringLiteral("25")));
        QCOMPARE(help.currentKey(), QStringLiteral("ERR 25"));
        QVERIFY(!help.showTopic(QStringLiteral("NOSUCHWORD")));

        help.setSearch(QStringLiteral("following error"));
        QVERIFY(help.visibleTopicCount() >= 1);
        QVERIFY(help.visibleTopicCount() < 20);
        help.setSearch(QString());
        const int all = int(cat::commands().size() + cat::variables().size() + cat::errors().size());
        QCOMPARE(help.visibleTopicCount(), all);
        QVERIFY(help.showTopic(QStringLiteral("intro")));
        QVERIFY(help.pageText().contains(QStringLiteral("F3")));
    }

    void theReferenceFollowsTheDriveFamily() {
        MainWindow window;
        window.show();
        window.connectDrive(app::ConnectionChoice::simulator(drive_core::DriveFamily::Sc750));
        app::HelpBrowser* help = window.helpBrowser();
        QCOMPARE(help->windowTitle(), QStringLiteral("SC750 Reference"));
        QVERIFY(help->showTopic(QStringLiteral("go.vel")));
        QCOMPARE(help->currentKey(), QStringLiteral("GO.VEL"));
        QVERIFY(help->pageText().contains(QStringLiteral("Statement")));
        QVERIFY(help->showTopic(QStringLiteral("RUN.SPEED")));
        QVERIFY(help->pageText().contains(QStringLiteral("Range")));
        QVERIFY(help->showTopic(QStringLiteral("FAULT 4")));
        QVERIFY(help->pageText().contains(QStringLiteral("front panel")));
        QVERIFY(!help->showTopic(QStringLiteral("VMAX"))); // a BDS5 variable: not the SC750's
        QVERIFY(help->showTopic(QStringLiteral("intro")));
        QVERIFY(help->pageText().contains(QStringLiteral("Ctrl+R")));

        window.connectDrive(app::ConnectionChoice::simulator(drive_core::DriveFamily::Pmc960));
        QCOMPARE(help->windowTitle(), QStringLiteral("PMC-960 Reference"));
        QVERIFY(help->showTopic(QStringLiteral("#b6")));
        QVERIFY(help->pageText().contains(QStringLiteral("#B6")));
        QVERIFY(help->showTopic(QStringLiteral("TGP")));
        QVERIFY(help->pageText().contains(QStringLiteral("Range")));
        const QStringList texts = [&window] {
            QStringList out;
            for (QAction* menu : window.menuBar()->actions())
                if (menu->menu())
                    for (QAction* a : menu->menu()->actions()) out << a->text();
            return out;
        }();
        QVERIFY(texts.contains(QStringLiteral("PMC-960 &Reference")));

        window.connectDrive(app::ConnectionChoice::simulator(drive_core::DriveFamily::Bds5));
        QVERIFY(help->showTopic(QStringLiteral("VMAX")));
    }

    void helpMenuOpensTheReference() {
        MainWindow window;
        window.show();
        QVERIFY(!window.helpBrowser()->isVisible());
        QVERIFY(window.helpBrowser()->showTopic(QStringLiteral("ERR 25")));
        QVERIFY(window.helpBrowser()->isVisible());
    }
};

QTEST_MAIN(OptionsHelpTest)
#include "options_help_test.moc"
