// PMC-960 tour steps: connect, download a demo program, move, grab the editor, the two docks and the error log.
#include "pmc960_tour_steps.h"

#include "editor_area.h"
#include "editor_tabs.h"
#include "main_window.h"

#include "drive_core/simulator_controls.h"
#include "editor/help_popup.h"
#include "errors/error_log_dock.h"
#include "errors/error_log_model.h"
#include "editor/program_editor.h"
#include "editor/mpl_language.h"
#include "variables/variable_browser.h"
#include "variables/variable_model.h"
#include "variables/variable_sync.h"
#include "families/pmc960/pmc960_program_transfer.h"
#include "families/pmc960/pmc960_status_dock.h"
#include "families/pmc960/pmc960_workspace.h"
#include "scope/variable_watcher.h"
#include "scope/watch_view.h"
#include "serialport/simulator_link.h"

#include <QDockWidget>
#include <QPointer>
#include <QTimer>

#include <memory>
#include <optional>

namespace app {

namespace {
// The manual's loop examples (13, 14) joined into one program, with a homing routine in front.
const char* kDemo = R"(@.PMC-960 demo: index forward, back, repeat
@H
A3500
V400
OB1:1
@G
I4000+,
BW1
LG2999
@W
I,-
LW19
E
)";

Pmc960Workspace* pmc960(MainWindow& window) {
    return static_cast<Pmc960Workspace*>(window.workspace(drive_core::DriveFamily::Pmc960));
}

// ESTOP' on the simulator's bench (MOTION input off = ESTOP' asserted).
void estop(MainWindow& window, bool asserted) {
    if (auto* simulator = qobject_cast<serialport::SimulatorLink*>(pmc960(window)->link()))
        simulator->control([asserted](drive_core::SimulatorControls& bench) { bench.setMotionInput(!asserted); });
}
} // namespace

std::vector<ScreenshotTour::Step> pmc960TourSteps(MainWindow& window) {
    std::vector<ScreenshotTour::Step> steps;
    auto demo = std::make_shared<QPointer<editor::ProgramEditor>>();
    auto downloaded = std::make_shared<bool>(false);
    steps.push_back({.name = QStringLiteral("pmc960-connect"),
                     .act = [&window, demo, downloaded] {
                         window.connectDrive(ConnectionChoice::simulator(drive_core::DriveFamily::Pmc960));
                         *demo = window.editorArea()->tabs()->addEditor(QStringLiteral("index-demo.mpl"));
                         (*demo)->setText(QString::fromLatin1(kDemo));
                         QObject::connect(&pmc960(window)->transfer(), &Pmc960ProgramTransfer::downloadFinished,
                                          &window, [downloaded] { *downloaded = true; });
                     },
                     .ready = [&window] {
                         Pmc960Workspace* ws = pmc960(window);
                         return ws->session() && ws->session()->state() == serialport::Pmc960Session::State::Ready &&
                                ws->parameterBrowser()->sync().pending() == 0;
                     }});
    steps.push_back({.name = QStringLiteral("pmc960-download"),
                     .act = [&window, demo] { pmc960(window)->transfer().download(*demo); },
                     .ready = [downloaded] { return *downloaded; }});
    steps.push_back({.name = QStringLiteral("mpl-editor"),
                     .act = [demo] {
                         if (!*demo) return;
                         (*demo)->setFocus();
                         (*demo)->setCursorPosition(6, 0); // I4000+,
                         if (auto* language = editor::MplLanguage::of(*demo)) language->showHelpAtCursor();
                     },
                     .ready = [demo] {
                         auto* language = *demo ? editor::MplLanguage::of(*demo) : nullptr;
                         return language && language->helpPopup()->isVisible();
                     },
                     .grab = [&window] { return TourShot::withPopups(&window); }, // with the help it waits for
                     .cleanUp = [demo] {
                         if (auto* language = *demo ? editor::MplLanguage::of(*demo) : nullptr) language->hideHelp();
                     }});
    auto settle = std::make_shared<int>(0); // polls to wait after an index was sent before judging it
    steps.push_back({.name = QStringLiteral("pmc960-status"),
                     .act = [&window, settle] {
                         *settle = 40;
                         Pmc960StatusDock* status = pmc960(window)->statusDock();
                         status->setFloating(true); // before show(): docked first, it would grow the main window
                         status->show();
                         status->resize(420, 560);
                         status->sendCommand(QStringLiteral("SM2"));
                         status->sendCommand(QStringLiteral("OB5:F"));
                         status->sendCommand(QStringLiteral("V30")); // 3,000 counts/s: caught mid-move
                         status->sendCommand(QStringLiteral("I12000+"));
                     },
                     .ready = [&window, settle] {
                         Pmc960StatusDock* status = pmc960(window)->statusDock();
                         const int position = status->value(QStringLiteral("position")).toInt();
                         // A stalled machine can miss the 4 s move between two polls: once an index has ended
                         // at either end, the next goes the other way, until one is caught mid-move.
                         if (*settle > 0) {
                             --*settle;
                         } else if (status->value(QStringLiteral("togo")) == QLatin1String("0") &&
                                    status->value(QStringLiteral("velocity")).toInt() == 0) {
                             status->sendCommand(position >= 6000 ? QStringLiteral("I12000-") : QStringLiteral("I12000+"));
                             *settle = 40;
                         }
                         return position > 1000 && position < 11000 && status->value(QStringLiteral("velocity")).toInt() != 0 &&
                                status->value(QStringLiteral("outputs")) == QLatin1String("0005");
                     },
                     .grab = [&window] { return TourShot::of(pmc960(window)->statusDock()); },
                     // No clean-up: left floating, as docked beside the parameter table it would make the main window
                     // taller than 800 px, and the later shots read its polls.
                 });
    steps.push_back({.name = QStringLiteral("pmc960-parameters"),
                     .act = [&window] {
                         QDockWidget* table = pmc960(window)->parameterDock();
                         table->setFloating(true); // before show(): docked first, it would grow the main window
                         table->show();
                         table->resize(900, 600);
                         pmc960(window)->parameterBrowser()->reveal(QStringLiteral("TGP"));
                         pmc960(window)->parameterBrowser()->editValue(QStringLiteral("TGP"), QStringLiteral("24"));
                     },
                     .ready = [&window] {
                         const VariableBrowser* browser = pmc960(window)->parameterBrowser();
                         return browser->sync().pending() == 0 &&
                                browser->model().second(QStringLiteral("TGP")) == QLatin1String("24");
                     },
                     .grab = [&window] { return TourShot::of(pmc960(window)->parameterDock()); },
                     .cleanUp = [&window] {
                         QDockWidget* table = pmc960(window)->parameterDock();
                         table->hide(); // hidden first: docked while shown, it would grow the main window
                         table->setFloating(false);
                     }});
    // Watch Variables on the PMC-960: position and following error from status polls during an index.
    auto watch = std::make_shared<QPointer<WatchView>>();
    auto indexed = std::make_shared<bool>(false);
    steps.push_back({.name = QStringLiteral("watch-pmc960"),
                     .act = [&window, watch] {
                         WatchView* view = *watch = pmc960(window)->watchVariables();
                         view->resize(900, 440);
                         view->watch({QStringLiteral("G"), QStringLiteral("SF")});
                     },
                     .ready = [&window, watch, indexed] {
                         if (!*watch || (*watch)->watcher().store().channelCount() == 0) return false;
                         const auto& samples = (*watch)->watcher().store().channel(0).samples;
                         Pmc960StatusDock* status = pmc960(window)->statusDock();
                         // The index of the status shot has ended (a move while moving is refused, #B2): back.
                         if (!*indexed && samples.size() > 10 && status->value(QStringLiteral("togo")) == QLatin1String("0")) {
                             for (const char* command : {"SM2", "V40", "I30000-"})
                                 status->sendCommand(QString::fromLatin1(command));
                             *indexed = true;
                         }
                         // the index has run for a while: a ramp with samples on both sides of it
                         return *indexed && samples.size() > 40 && samples.front().value - samples.back().value > 20000;
                     },
                     .grab = [watch] { return TourShot::of(*watch); },
                     .cleanUp = [watch] {
                         if (*watch) (*watch)->close();
                     }});
    // The error log decoding the controller's codes: a move refused while idle (#B6), ESTOP' asserted on the
    // bench during a move (the asynchronous #E0), and the `&` snapshot of that last error.
    steps.push_back({.name = QStringLiteral("error-log-pmc960"),
                     .act = [&window] {
                         ErrorLogDock* errors = window.errorLogDock();
                         errors->setFloating(true); // before show(): docked first, it would grow the main window
                         errors->show();
                         errors->resize(1100, 300);
                         errors->raise();
                         Pmc960StatusDock* status = pmc960(window)->statusDock();
                         for (const char* command : {"SM0", "I4000+"})
                             status->sendCommand(QString::fromLatin1(command));
                         // Each step on an event, not after a fixed time (a busy machine ran ESTOP' before the
                         // move had started, and once lost the move sent in one burst with the refused index):
                         // the move once the #B6 of the refused index is in the log; ESTOP' once the status
                         // shows that move under way (forward and past where it started: a status from the
                         // earlier steps' moves must not count); released and the last error read once the
                         // #E0 is in the log.
                         auto start = std::make_shared<std::optional<int>>();
                         auto* sequence = new QTimer(errors);
                         sequence->setInterval(50);
                         QObject::connect(sequence, &QTimer::timeout, errors, [&window, errors, status, sequence, start] {
                             const ErrorLogModel& m = errors->model();
                             bool e0 = false, b6 = false;
                             for (int row = 0; row < m.rowCount(); ++row) {
                                 const bool reported = m.entry(row).origin != ErrorLogModel::Origin::History;
                                 e0 = e0 || (m.entry(row).code == 0xE0 && reported);
                                 b6 = b6 || (m.entry(row).code == 0xB6 && reported);
                             }
                             if (e0) {
                                 sequence->deleteLater();
                                 estop(window, false);
                                 errors->readHistory();
                             } else if (b6 && !*start) {
                                 *start = status->value(QStringLiteral("position")).toInt();
                                 for (const char* command : {"SM2", "V400", "I400000+"})
                                     status->sendCommand(QString::fromLatin1(command));
                             } else if (!sequence->property("estop").toBool() && *start &&
                                        status->value(QStringLiteral("velocity")).toInt() > 0 &&
                                        status->value(QStringLiteral("position")).toInt() > **start + 1000) {
                                 sequence->setProperty("estop", true);
                                 estop(window, true);
                             }
                         });
                         sequence->start();
                     },
                     .ready = [&window] {
                         const ErrorLogModel& m = window.errorLogDock()->model();
                         int reported = 0, history = 0;
                         for (int row = 0; row < m.rowCount(); ++row) {
                             const bool shown = m.entry(row).code == 0xB6 || m.entry(row).code == 0xE0;
                             (m.entry(row).origin == ErrorLogModel::Origin::History ? history : reported) += shown;
                         }
                         return reported >= 2 && history >= 1;
                     },
                     .grab = [&window] { return TourShot::of(window.errorLogDock()); },
                     .cleanUp = [&window, demo] {
                         window.errorLogDock()->setFloating(false);
                         window.errorLogDock()->hide();
                         if (*demo) (*demo)->setModified(false);
                         window.connectDrive(ConnectionChoice::simulator(drive_core::DriveFamily::Bds5));
                     },
                     .state = [&window] {
                         const ErrorLogModel& m = window.errorLogDock()->model();
                         QStringList logged;
                         for (int row = 0; row < m.rowCount(); ++row)
                             logged << QStringLiteral("%1%2").arg(m.entry(row).code, 2, 16, QLatin1Char('0')).arg(
                                           m.entry(row).origin == ErrorLogModel::Origin::History ? QStringLiteral(" (&)")
                                                                                                 : QString());
                         Pmc960StatusDock* status = pmc960(window)->statusDock();
                         return QStringLiteral("log: %1; status position %2, velocity %3")
                             .arg(logged.join(QStringLiteral(", ")), status->value(QStringLiteral("position")),
                                  status->value(QStringLiteral("velocity")));
                     }});
    return steps;
}

} // namespace app
