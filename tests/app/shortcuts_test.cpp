// No two actions in effect share a shortcut, and no two menus of the menu bar (nor two entries of one menu)
// share a mnemonic, for every drive family (issue 19, item 12: Ctrl+Shift+R was both Run Label and
// Scope > From Drive, so Qt called it ambiguous and neither worked; Alt+V and Alt+C each opened two menus).
#include "app/drive/connection_choice.h"
#include "app/main_window.h"

#include <QAction>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QStandardPaths>
#include <QTest>

using app::MainWindow;
using drive_core::DriveFamily;

namespace {
// The visible actions of a menu bar's visible menus, their submenus included, with the menu path.
void collect(const QMenu* menu, const QString& path, QMultiMap<QString, QString>& shortcuts, QStringList& clashes) {
    QMap<QChar, QString> mnemonics;
    for (QAction* action : menu->actions()) {
        if (!action->isVisible() || action->isSeparator()) continue;
        const QString text = action->text();
        const qsizetype amp = text.indexOf(QLatin1Char('&'));
        if (amp >= 0 && amp + 1 < text.size() && text.at(amp + 1) != QLatin1Char('&')) {
            const QChar key = text.at(amp + 1).toLower();
            if (mnemonics.contains(key))
                clashes << QStringLiteral("Alt+%1 in %2: '%3' and '%4'").arg(key, path, mnemonics.value(key), text);
            mnemonics.insert(key, text);
        }
        if (action->menu()) {
            collect(action->menu(), path + QStringLiteral(" > ") + text, shortcuts, clashes);
            continue;
        }
        for (const QKeySequence& key : action->shortcuts())
            shortcuts.insert(key.toString(QKeySequence::PortableText), path + QStringLiteral(" > ") + text);
    }
}

QStringList clashesIn(const MainWindow& window) {
    QStringList clashes;
    QMultiMap<QString, QString> shortcuts;
    QMap<QChar, QString> menus;
    for (QAction* top : window.menuBar()->actions()) {
        if (!top->isVisible() || !top->menu()) continue;
        const QString text = top->text();
        const qsizetype amp = text.indexOf(QLatin1Char('&'));
        if (amp >= 0 && amp + 1 < text.size()) {
            const QChar key = text.at(amp + 1).toLower();
            if (menus.contains(key))
                clashes << QStringLiteral("Alt+%1 opens '%2' and '%3'").arg(key, menus.value(key), text);
            menus.insert(key, text);
        }
        collect(top->menu(), text, shortcuts, clashes);
    }
    // Actions of the window itself (toolbars, docks' toggles) that no menu holds.
    for (QAction* action : window.findChildren<QAction*>()) {
        if (!action->isVisible() || action->shortcuts().isEmpty()) continue;
        bool inMenu = false;
        for (const QObject* owner : action->associatedObjects()) inMenu = inMenu || qobject_cast<const QMenu*>(owner);
        if (inMenu) continue;
        bool onWindow = false;
        for (const QObject* owner : action->associatedObjects()) onWindow = onWindow || owner == &window;
        if (!onWindow) continue;
        for (const QKeySequence& key : action->shortcuts())
            shortcuts.insert(key.toString(QKeySequence::PortableText), QStringLiteral("window > ") + action->text());
    }
    for (const QString& key : shortcuts.uniqueKeys()) {
        QStringList owners = shortcuts.values(key);
        owners.removeDuplicates();
        if (owners.size() > 1) clashes << QStringLiteral("%1 is bound to %2").arg(key, owners.join(QStringLiteral(", ")));
    }
    return clashes;
}
} // namespace

class ShortcutsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    void noTwoActionsShareAShortcutOrAMnemonic_data() {
        QTest::addColumn<DriveFamily>("family");
        QTest::newRow("BDS5") << DriveFamily::Bds5;
        QTest::newRow("SC750") << DriveFamily::Sc750;
        QTest::newRow("PMC-960") << DriveFamily::Pmc960;
    }

    void noTwoActionsShareAShortcutOrAMnemonic() {
        QFETCH(DriveFamily, family);
        MainWindow window;
        window.show();
        window.connectDrive(app::ConnectionChoice::simulator(family));
        const QStringList clashes = clashesIn(window);
        QVERIFY2(clashes.isEmpty(), qPrintable(clashes.join(QLatin1Char('\n'))));
    }
};

QTEST_MAIN(ShortcutsTest)
#include "shortcuts_test.moc"
