// Docks tour steps: each view floated at a readable size, filled from the simulated drive through the
// session (the I/O panel through the simulator's bench), grabbed, then put away.
#include "docks_tour_steps.h"

#include "families/bds5/bds5_workspace.h"

#include "families/bds5/drive_connection.h"
#include "main_window.h"

#include "families/bds5/dep01/dep01_panel.h"
#include "errors/error_log_dock.h"
#include "errors/error_log_model.h"
#include "families/bds5/io_panel.h"
#include "serialport/simulator_link.h"
#include "variables/variable_model.h"
#include "variables/variable_browser.h"
#include "variables/variables_dock.h"
#include "families/bds5/wizard/parameter_page.h"
#include "families/bds5/wizard/setup_wizard.h"
#include "families/bds5/wizard/wizard_changes.h"

#include <QCheckBox>
#include <QPointer>
#include <QPushButton>
#include <QTimer>
#include <QTreeView>

#include <memory>

namespace app {

namespace {
bool driveReady(MainWindow& window) {
    const auto* session = window.connection().session();
    return session && session->state() == serialport::Bds5Session::State::Ready &&
           session->mode() == serialport::Bds5Mode::Interactive;
}

void send(MainWindow& window, std::initializer_list<const char*> lines) {
    for (const char* line : lines) window.connection().sendCommand(QString::fromLatin1(line));
}

// Floated before it is shown: shown docked first, a tall dock raises the main window's minimum height and the
// window grows (to 813 px once, and every later shot of it with it).
void floatDock(QDockWidget* dock, QSize size) {
    dock->setFloating(true);
    dock->show();
    dock->resize(size);
    dock->raise();
}

void bench(MainWindow& window, std::function<void(drive_core::SimulatorControls&)> change) {
    auto* session = window.connection().session();
    if (auto* simulator = session ? qobject_cast<serialport::SimulatorLink*>(&session->link()) : nullptr)
        simulator->control(std::move(change));
}

int rowsFrom(const ErrorLogModel& model, ErrorLogModel::Origin origin) {
    int n = 0;
    for (int row = 0; row < model.rowCount(); ++row) n += model.entry(row).origin == origin;
    return n;
}

// Opens the wizard at a page and waits for what it reads.
ScreenshotTour::Step wizardStep(MainWindow& window, std::shared_ptr<QPointer<SetupWizard>> wizard, const QString& name,
                                const QString& title, std::function<void(SetupWizard&)> act,
                                std::function<bool(SetupWizard&)> ready) {
    return {.name = name,
            .act =
                [&window, wizard, title, act] {
                    if (!*wizard) {
                        *wizard = SetupWizard::openFor(window.connection(), &window);
                        (*wizard)->resize(900, 620);
                    }
                    SetupWizard& w = **wizard;
                    const int id = w.pageIdOf(title);
                    const bool behind = w.visitedIds().contains(id); // visited pages lie behind
                    for (int guard = 0; w.currentId() != id && guard < 32; ++guard) behind ? w.back() : w.next();
                    if (act) act(w);
                },
            .ready = [wizard, ready] { return *wizard && (!ready || ready(**wizard)); },
            .grab = [wizard] { return TourShot::of(*wizard); }};
}
} // namespace

std::vector<ScreenshotTour::Step> docksTourSteps(MainWindow& window) {
    std::vector<ScreenshotTour::Step> steps;
    VariablesDock* variables = window.bds5().variablesDock();
    steps.push_back({.name = QStringLiteral("variable-browser"),
                     .act =
                         [&window, variables] {
                             send(window, {"X1=1234", "X2=-50", "X3=7"});
                             floatDock(variables, {1000, 640});
                             variables->browser()->model().setPinned(QStringLiteral("X1"), true);
                             variables->browser()->model().setPinned(QStringLiteral("VMAX"), true);
                             variables->browser()->reveal(QStringLiteral("PFB"));
                         },
                     .ready =
                         [variables] {
                             const VariableModel& m = variables->browser()->model();
                             return !m.value(QStringLiteral("PFB")).isEmpty() &&
                                    !m.value(QStringLiteral("VCMD")).isEmpty() &&
                                    !m.value(QStringLiteral("ACC")).isEmpty() &&
                                    !m.value(QStringLiteral("ADEN")).isEmpty() &&
                                    !m.value(QStringLiteral("IDEN")).isEmpty() &&
                                    m.value(QStringLiteral("X1")) == QLatin1String("1234");
                         },
                     .grab = [variables] { return TourShot::of(variables); },
                     .cleanUp = [variables] { variables->hide(); }});

    ErrorLogDock* errors = window.errorLogDock();
    steps.push_back(
        {.name = QStringLiteral("error-log"),
         .act =
             [&window, errors] {
                 floatDock(errors, {1100, 360});
                 // A warning, two breaks, and a limit switch tripped while enabled (ERR 24 disables).
                 send(window, {"FOO", "GOTO 1", "X9=1/0", "PLIM OFF", "EN"});
                 QTimer::singleShot(1500, errors, [&window] {
                     bench(window, [](drive_core::SimulatorControls& c) { c.setLimitSwitches(true, false); });
                 });
                 QTimer::singleShot(2000, errors, [&window, errors] {
                     bench(window, [](drive_core::SimulatorControls& c) { c.setLimitSwitches(false, false); });
                     send(window, {"DIS"});
                     errors->readHistory();
                 });
             },
         .ready =
             [&window, errors] {
                 const ErrorLogModel& m = errors->model();
                 return rowsFrom(m, ErrorLogModel::Origin::Reported) >= 3 && driveReady(window) &&
                        rowsFrom(m, ErrorLogModel::Origin::History) >= 4;
             },
         .grab = [errors] { return TourShot::of(errors); },
         .cleanUp = [errors] { errors->hide(); }});

    auto wizard = std::make_shared<QPointer<SetupWizard>>();
    steps.push_back(wizardStep(window, wizard, QStringLiteral("wizard-units"),
                               QStringLiteral("Machine Setup \u2014 Units"), nullptr, [](SetupWizard& w) {
                                   for (const char* n : {"PNUM", "PDEN", "VNUM", "VDEN", "ANUM", "ADEN", "INUM", "IDEN",
                                                         "PXNUM", "PXDEN", "VXNUM", "VXDEN"})
                                       if (w.model().value(QString::fromLatin1(n)).isEmpty()) return false;
                                   return true;
                               }));
    steps.push_back(wizardStep(
        window, wizard, QStringLiteral("wizard-input-test"), QStringLiteral("Input Test"),
        [&window](SetupWizard&) {
            bench(window, [](drive_core::SimulatorControls& c) {
                for (int i : {2, 5, 6, 11}) c.setInput(i, true);
            });
        },
        [](SetupWizard& w) {
            return w.model().value(QStringLiteral("I5")) == QLatin1String("1") &&
                   !w.model().value(QStringLiteral("I16")).isEmpty();
        }));
    steps.push_back(wizardStep(
        window, wizard, QStringLiteral("wizard-summary"), QStringLiteral("Send Variables"),
        [](SetupWizard& w) {
            for (ParameterPage* page : w.parameterPages()) {
                if (page->names().contains(QStringLiteral("PMAX"))) {
                    page->setText(QStringLiteral("PMAX"), QStringLiteral("400000"));
                    page->setText(QStringLiteral("PMIN"), QStringLiteral("-400000"));
                    page->setText(QStringLiteral("PLIM"), QStringLiteral("ON"));
                }
                if (page->names().contains(QStringLiteral("PNUM")))
                    page->setText(QStringLiteral("PDEN"), QStringLiteral("4"));
            }
        },
        [](SetupWizard& w) {
            const QStringList names = w.changes().changedNames();
            return names.size() >= 4 && std::all_of(names.cbegin(), names.cend(), [&w](const QString& n) {
                       return !w.changes().change(n).original.isEmpty(); // what the drive holds, read
                   });
        }));
    steps.back().cleanUp = [wizard] {
        if (*wizard) (*wizard)->reject(); // nothing was sent: closing discards the changes
    };

    Dep01Panel* dep = window.bds5().dep01Panel();
    steps.push_back(
        {.name = QStringLiteral("dep01"),
         .act =
             [&window, dep] {
                 floatDock(dep, {560, 420});
                 dep->depSwitch()->setChecked(true);
                 dep->clearDisplay();
                 send(window, {"P \"SPEED (RPM)?   ATTN: MENU\""});
             },
         .ready = [&window,
                   dep] { return driveReady(window) && dep->screen().line(0).startsWith(QStringLiteral("SPEED")); },
         .grab = [dep] { return TourShot::of(dep); },
         .cleanUp = [dep] { dep->hide(); }});

    IoPanel* io = window.bds5().ioPanel();
    steps.push_back({.name = QStringLiteral("io-panel"),
                     .act =
                         [&window, io] {
                             floatDock(io, {620, 560});
                             send(window, {"O1 ON", "O3 ON", "O4 ON"});
                             bench(window, [](drive_core::SimulatorControls& c) {
                                 for (int i : {2, 5, 6, 11}) c.setInput(i, true);
                                 c.setLoadTorque_Nm(0.35);
                             });
                         },
                     .ready = [io] { return io->outputLit(1) && io->outputLit(4) && io->inputButton(5)->isChecked(); },
                     .grab = [io] { return TourShot::of(io); },
                     .cleanUp = [io] { io->hide(); }});
    return steps;
}

} // namespace app
