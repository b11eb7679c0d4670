// SC750 tour steps: connect, run, break, inspect, grab; then a compile error; then back to the BDS5.
#include "sc750_tour_steps.h"

#include "editor_area.h"
#include "editor_tabs.h"
#include "main_window.h"
#include "terminal_dock.h"

#include "editor/program_editor.h"
#include "families/sc750/sc750_controller_menu.h"
#include "families/sc750/sc750_debugger.h"
#include "families/sc750/sc750_output_dock.h"
#include "families/sc750/sc750_setup_data_table.h"
#include "families/sc750/sc750_setup_dialog.h"
#include "families/sc750/sc750_seven_segment.h"
#include "families/sc750/sc750_status_display.h"
#include "variables/variable_browser.h"
#include "families/sc750/sc750_variables_dock.h"
#include "families/sc750/sc750_workspace.h"
#include "scope/variable_watcher.h"
#include "scope/watch_view.h"

#include <QDialog>
#include <QLabel>
#include <QPointer>
#include <QTableWidget>

#include <memory>

namespace app {

namespace {
// A small program in the manual's layout: declarations, a labelled loop, PRINT to the output window.
const char* kDemo = R"('----- Motion Dialogue demo: index, report, repeat -----
'----- Variable Definitions -----
DIM Count AS INTEGER
DIM Distance AS FLOAT

'----- Main Program -----
Count = 0
Distance = 2.5            ' revolutions per index
PAUSE.TIME = 0.4
Index_Loop:
    Count = Count + 1
    PRINT "Index"; Count; "of"; Distance; "revs"
    ENABLE = 1
    INDEX.DIST = 10240    ' 2.5 revs at 4096 counts/rev
    GO.INCR
    PAUSE
    GOTO Index_Loop
END
)";
constexpr int kPrintLine = 11; // 0-based: the PRINT

// The same program with a typing mistake the compiler stops at.
const char* kBroken = R"('----- Motion Dialogue demo with a mistake -----
DIM Count AS INTEGER
Count = 0
Index_Loop:
    Count = Count + 1
    PRINT "Index"; Count
    GOTO Index_Lop
END
)";

Sc750Workspace* sc750(MainWindow& window) {
    return static_cast<Sc750Workspace*>(window.workspace(drive_core::DriveFamily::Sc750));
}
} // namespace

std::vector<ScreenshotTour::Step> sc750TourSteps(MainWindow& window) {
    std::vector<ScreenshotTour::Step> steps;
    if (!sc750(window)) return steps;
    auto demo = std::make_shared<QPointer<editor::ProgramEditor>>();
    steps.push_back({.name = QStringLiteral("sc750-connect"),
                     .act = [&window, demo] {
                         window.connectDrive(ConnectionChoice::simulator(drive_core::DriveFamily::Sc750));
                         EditorTabs* tabs = window.editorArea()->tabs();
                         *demo = tabs->addEditor(QStringLiteral("index.bas"));
                         (*demo)->setText(QString::fromLatin1(kDemo));
                         (*demo)->setModified(false);
                         tabs->refreshTab(*demo);
                     },
                     .ready = [&window] { return sc750(window)->isConnected(); }});
    steps.push_back({.name = QStringLiteral("sc750-run"),
                     .act = [&window] { sc750(window)->debugger().run(); },
                     .ready = [&window] {
                         return sc750(window)->outputDock()->text().contains(QStringLiteral("Index 3 "));
                     }});
    // The front-panel display in the status bar: "8." (enabled, decimal point = a program runs), with the
    // output window above it: the bottom of the window.
    steps.push_back({.name = QStringLiteral("sc750-status-display"),
                     .ready =
                         [&window] {
                             const Sc750SevenSegment* digit = sc750(window)->statusDisplay()->digit();
                             return digit->decimalPoint() && digit->shown() == QLatin1Char('8');
                         },
                     .grab =
                         [&window] {
                             return TourShot::of(&window).cropped(
                                 QRect(0, window.height() - 300, window.width(), 300));
                         },
                     .text =
                         [&window] {
                             const Sc750StatusDisplay* display = sc750(window)->statusDisplay();
                             return display->digit()->characters() +
                                    (display->digit()->decimalPoint() ? QStringLiteral(".") : QString()) +
                                    QLatin1Char(' ') + display->meaning();
                         }});
    // Watch Variables on the SC750: POSITION and VELOCITY read with G frames while the demo indexes.
    auto watch = std::make_shared<QPointer<WatchView>>();
    steps.push_back({.name = QStringLiteral("watch-sc750"),
                     .act = [&window, watch] {
                         WatchView* view = *watch = sc750(window)->watchVariables();
                         view->resize(900, 440);
                         view->watch({QStringLiteral("POSITION"), QStringLiteral("VELOCITY")});
                     },
                     .ready = [watch] {
                         if (!*watch || (*watch)->watcher().store().channelCount() < 2) return false;
                         const auto& samples = (*watch)->watcher().store().channel(0).samples;
                         // three indexes or more on the chart
                         return samples.size() > 40 && samples.back().value - samples.front().value > 3 * 10240;
                     },
                     .grab = [watch] { return TourShot::of(*watch); },
                     .cleanUp = [watch] {
                         if (*watch) (*watch)->close();
                     }});
    steps.push_back({.name = QStringLiteral("sc750-break"),
                     .act = [&window, demo] {
                         if (*demo) sc750(window)->debugger().toggleBreakpointAt(**demo, kPrintLine);
                     },
                     .ready = [&window] {
                         return sc750(window)->debugger().state() == Sc750Debugger::State::AtBreakpoint;
                     }});
    steps.push_back({.name = QStringLiteral("motion-dialogue"),
                     .act = [&window] {
                         // The program over an output window a third of the height, as a user opens it: the
                         // scope steps before left the bottom docks tall.
                         window.resizeDocks({window.terminalDock()}, {window.height() / 3}, Qt::Vertical);
                         Sc750VariablesDock* vars = sc750(window)->variablesDock();
                         vars->show();
                         for (const char* name : {"COUNT", "DISTANCE", "PAUSE.TIME", "RUN.SPEED", "POS.COMMAND"})
                             vars->readVariable(QString::fromLatin1(name));
                     },
                     .ready = [&window] {
                         return !sc750(window)->variablesDock()->value(QStringLiteral("POS.COMMAND")).isEmpty();
                     },
                     .grab = [&window] { return TourShot::of(&window); }});
    // The variable browser: every predefined variable, grouped, the rows in view read live.
    steps.push_back({.name = QStringLiteral("variables-sc750-all"),
                     .act = [&window] {
                         Sc750VariablesDock* vars = sc750(window)->variablesDock();
                         vars->showAllVariables();
                         vars->setFloating(true);
                         vars->resize(1040, 640);
                         vars->browser()->reveal(QStringLiteral("ACCEL.RATE"));
                     },
                     .ready = [&window] {
                         VariableBrowser* browser = sc750(window)->variablesDock()->browser();
                         // all in view read, down to the last row the shot shows
                         for (const char* name : {"ACCEL.RATE", "RUN.SPEED", "POSITION", "IFB", "ENABLE", "MODEL"})
                             if (browser->value(QString::fromLatin1(name)).isEmpty()) return false;
                         return true;
                     },
                     .grab = [&window] { return TourShot::of(sc750(window)->variablesDock()); },
                     .cleanUp = [&window] {
                         Sc750VariablesDock* vars = sc750(window)->variablesDock();
                         vars->setFloating(false);
                         vars->focusName();
                     }});
    steps.push_back({.name = QStringLiteral("sc750-function-call"),
                     .act = [&window] { sc750(window)->showFunctionCall(); },
                     .ready = [&window] {
                         auto* dialog = window.findChild<QWidget*>(QStringLiteral("sc750FunctionDialog"));
                         return dialog && dialog->isVisible();
                     },
                     .grab = [&window] {
                         return TourShot::of(window.findChild<QWidget*>(QStringLiteral("sc750FunctionDialog")));
                     },
                     .cleanUp = [&window] {
                         if (auto* dialog = window.findChild<QWidget*>(QStringLiteral("sc750FunctionDialog"))) dialog->close();
                     }});
    // Manual for the R45G with a load as heavy as its rotor: the set-up data above, the computed values below.
    steps.push_back(
        {.name = QStringLiteral("sc750-controller-setup"),
         .act =
             [&window] {
                 auto* menu = qobject_cast<Sc750ControllerMenu*>(sc750(window)->menus().at(1));
                 auto* dialog = qobject_cast<Sc750SetupDialog*>(menu->controllerSetUp());
                 dialog->setMotorPart(QStringLiteral("R45G"));
                 dialog->setManual(true);
                 dialog->setupDataTable()
                     ->valueItem(QStringLiteral("Load inertia"))
                     ->setText(QStringLiteral("1.84313"));
             },
         .ready =
             [&window] {
                 auto* dialog = window.findChild<Sc750SetupDialog*>(QStringLiteral("sc750SetupDialog"));
                 return dialog && dialog->isVisible() && dialog->controllerModel() != 0 &&
                        !dialog->table()->findItems(QStringLiteral("KVP"), Qt::MatchExactly).isEmpty();
             },
         .grab = [&window] { return TourShot::of(window.findChild<QWidget*>(QStringLiteral("sc750SetupDialog"))); },
         .cleanUp =
             [&window] {
                 if (auto* dialog = window.findChild<QDialog*>(QStringLiteral("sc750SetupDialog"))) dialog->reject();
             }});
    steps.push_back({.name = QStringLiteral("sc750-compile-error"),
                     .act = [&window, demo] {
                         Sc750Workspace* ws = sc750(window);
                         ws->variablesDock()->hide();
                         ws->outputDock()->hide();
                         if (*demo) (*demo)->setText(QString::fromLatin1(kBroken));
                         ws->debugger().compile();
                     },
                     .ready = [&window] { return !sc750(window)->debugger().lastError().isEmpty(); },
                     .grab = [&window] { return TourShot::of(&window); },
                     .cleanUp = [&window, demo] {
                         sc750(window)->debugger().reset();
                         sc750(window)->outputDock()->hide();
                         if (*demo) (*demo)->setModified(false);
                         window.connectDrive(ConnectionChoice::simulator(drive_core::DriveFamily::Bds5));
                     }});
    return steps;
}

} // namespace app
