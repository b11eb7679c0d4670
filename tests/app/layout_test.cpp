// The main window on a laptop's screen (issue 19, item 10): with every dock of a family open, the window still
// fits 1024×768 and 1366×768 (docks once forced it to 1827 px wide), the editor keeps a usable number of lines,
// and shrinking the window never leaves a dock wider than the window.
#include "app/drive/connection_choice.h"
#include "app/main_window.h"
#include "app/scope/measurements_table.h"
#include "app/status_bar_room.h"

#include "editor/program_editor.h"

#include <QDockWidget>
#include <QHeaderView>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTest>

using app::MainWindow;
using drive_core::DriveFamily;

Q_DECLARE_METATYPE(DriveFamily)

namespace {
// The action a menu opens the dock with: the Scope menu's own (it tabs the dock beside the terminal), else the
// dock's toggle in the View menu.
QAction* openingAction(const MainWindow& window, QDockWidget* dock) {
    for (QAction* action : window.findChildren<QAction*>())
        if (action->property("opensDock").value<QObject*>() == dock) return action;
    return dock->toggleViewAction();
}

// Every dock the user can open from the View and Scope menus in this family (a hidden toggle is another
// family's).
QList<QDockWidget*> openEveryDock(MainWindow& window) {
    QList<QDockWidget*> opened;
    for (QDockWidget* dock : window.findChildren<QDockWidget*>()) {
        if (!dock->toggleViewAction()->isVisible()) continue;
        dock->show();
        opened << dock;
    }
    return opened;
}

int visibleEditorLines(const MainWindow& window) {
    const editor::ProgramEditor* editor = window.editor();
    return editor->isVisible() ? editor->SendScintilla(QsciScintillaBase::SCI_LINESONSCREEN) : 0;
}
} // namespace

class LayoutTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true); // never touch the user's settings or saved layout
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDesk"));
    }

    void everyDockFitsALaptopScreen_data() {
        QTest::addColumn<DriveFamily>("family");
        QTest::addColumn<QSize>("screen");
        for (const QSize screen : {QSize(1024, 768), QSize(1366, 768)}) {
            const QByteArray size = QByteArray::number(screen.width()) + "x" + QByteArray::number(screen.height());
            QTest::newRow("bds5 " + size) << DriveFamily::Bds5 << screen;
            QTest::newRow("sc750 " + size) << DriveFamily::Sc750 << screen;
            QTest::newRow("pmc960 " + size) << DriveFamily::Pmc960 << screen;
        }
    }

    // Each dock the user opens, one at a time beside the terminal and outline, keeps the window on the screen.
    void everyDockFitsALaptopScreen() {
        QFETCH(DriveFamily, family);
        QFETCH(QSize, screen);
        MainWindow window(family);
        window.resize(screen);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QStringList tooBig;
        int opened = 0;
        for (QDockWidget* dock : window.findChildren<QDockWidget*>()) {
            if (dock->isVisible() || !dock->toggleViewAction()->isVisible()) continue;
            openingAction(window, dock)->trigger(); // as the user opens it, from the View or Scope menu
            QVERIFY2(dock->isVisible(), qPrintable(dock->windowTitle()));
            ++opened;
            window.resize(screen);
            QCoreApplication::processEvents();
            const QSize minimum = window.minimumSizeHint();
            // A dock of the bottom area opens as a tab beside the terminal, as wide as the window (the Error Log
            // once opened 318 px wide beside it).
            const bool narrowAtTheBottom = window.dockWidgetArea(dock) == Qt::BottomDockWidgetArea &&
                                           !dock->isFloating() && dock->width() < screen.width() * 3 / 4;
            if (window.size() != screen || dock->width() > screen.width() || narrowAtTheBottom)
                tooBig << QStringLiteral("%1 %6 px wide (window %2×%3, needs %4×%5)")
                              .arg(dock->windowTitle())
                              .arg(window.width())
                              .arg(window.height())
                              .arg(minimum.width())
                              .arg(minimum.height())
                              .arg(dock->width());
            openingAction(window, dock)->trigger();
            window.resize(screen);
            QCoreApplication::processEvents();
        }
        QVERIFY2(opened >= 4, qPrintable(QStringLiteral("only %1 docks to open").arg(opened)));
        QVERIFY2(tooBig.isEmpty(), qPrintable(tooBig.join(QStringLiteral("; "))));
    }

    void theEditorKeepsLinesOnSmallScreens_data() {
        QTest::addColumn<DriveFamily>("family");
        QTest::newRow("bds5") << DriveFamily::Bds5;
        QTest::newRow("sc750") << DriveFamily::Sc750;
        QTest::newRow("pmc960") << DriveFamily::Pmc960;
    }

    // At 800×600 the editor once showed 3 lines under the bottom docks: the program is what the user is there for.
    void theEditorKeepsLinesOnSmallScreens() {
        QFETCH(DriveFamily, family);
        MainWindow window(family);
        window.resize(800, 600);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QTRY_VERIFY2(visibleEditorLines(window) >= 12,
                     qPrintable(QStringLiteral("%1 editor lines at 800×600").arg(visibleEditorLines(window))));
        window.resize(1024, 768);
        openEveryDock(window);
        QTRY_VERIFY2(visibleEditorLines(window) >= 8, qPrintable(QStringLiteral("%1 editor lines at 1024×768, every "
                                                                                "dock open")
                                                                     .arg(visibleEditorLines(window))));
    }

    // Issue 19, item 11: "Verified: the drive's p" was all a 1366-pixel window showed of a transfer's result.
    void statusMessagesFitBesideTheCells_data() {
        QTest::addColumn<int>("width");
        QTest::newRow("1366") << 1366;
        QTest::newRow("1024") << 1024;
    }

    void statusMessagesFitBesideTheCells() {
        QFETCH(int, width);
        MainWindow window;
        window.connectDrive(app::ConnectionChoice::simulator());
        window.resize(width, 768);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QStatusBar* bar = window.statusBar();
        const QString message = QStringLiteral("Verified: the drive's program matches, 17 lines. Checksum 2B4E; "
                                               "the drive holds this program.");
        bar->showMessage(message);
        const int needed = bar->fontMetrics().horizontalAdvance(message);
        QTRY_VERIFY2(app::StatusBarRoom::messageRoom(*bar) >= needed,
                     qPrintable(QStringLiteral("%1 px for a %2 px message")
                                    .arg(app::StatusBarRoom::messageRoom(*bar))
                                    .arg(needed)));
        bar->clearMessage(); // the cells come back
        const auto* size = bar->findChild<QWidget*>(QStringLiteral("editorSizeLabel"));
        QVERIFY(size);
        QTRY_VERIFY(size->parentWidget()->width() > 0 && size->isVisible());
    }

    // "ershoot", "ise (ms": the measurement table's headers were squeezed to the dock's width.
    void measurementHeadersAreWhole() {
        app::MeasurementsTable table;
        table.resize(480, 200);
        table.show();
        QVERIFY(QTest::qWaitForWindowExposed(&table));
        const QHeaderView* header = table.horizontalHeader();
        for (int c = 0; c < table.columnCount(); ++c) {
            const QString text = table.horizontalHeaderItem(c)->text();
            const int needed = header->fontMetrics().horizontalAdvance(text);
            QVERIFY2(header->sectionSize(c) >= needed,
                     qPrintable(QStringLiteral("\"%1\": %2 px of %3").arg(text).arg(header->sectionSize(c)).arg(needed)));
        }
    }
};

QTEST_MAIN(LayoutTest)
#include "layout_test.moc"
