// The Tuning panel's frame (tuning_panel.h) and the pieces a family's own controls are built of (the BDS5's TUNE
// group): the controls scrolled on the left; on the right the scope over the runs table and its buttons. The runs table: one read-only row per run, whole rows selected, the run's number first, its gains
// changed second, and its measurements. GUI thread only.
#pragma once

#include <QList>
#include <QPushButton>
#include <QString>
#include <QStringList>

#include <optional>

namespace scope {
struct StepMetrics;
}

class QFormLayout;
class QLabel;
class QTableWidget;
class QWidget;

namespace app {

class ScopeView;

// Lays `controls`, `view`, `runs` and the buttons under it into `panel` (which gets the layout).
void layOutTuningFrame(QWidget* panel, QWidget* controls, ScopeView* view, QTableWidget* runs,
                       const QList<QPushButton*>& runButtons);
void setUpRunsTable(QTableWidget* runs, const QStringList& columns);

// A group of the controls column ("Gains", "Test move"): the box, titled, with a form in it.
struct ControlGroup {
    QWidget* box;
    QFormLayout* form;
};
ControlGroup addControlGroup(QWidget* panel, const QString& title);
void addRow(const ControlGroup& group, QWidget* row);
// The gains group's last row: Read from Drive, connected to the runner's readGains.
template <typename Runner>
void addReadGains(const ControlGroup& group, Runner* runner) {
    auto* read = new QPushButton(QObject::tr("Read from Drive"), group.box);
    QObject::connect(read, &QPushButton::clicked, runner, &Runner::readGains);
    addRow(group, read);
}

// The test move's Run Once / Run Continuously / Stop row, added to its form.
struct RunButtons {
    QPushButton* once = nullptr;
    QPushButton* loop = nullptr;
    QPushButton* stop = nullptr;

    // Run Once while no run is under way, Run Continuously while the runs are not continuous, Stop as told.
    void update(bool running, bool continuous, bool stoppable) const;
};
RunButtons addRunButtons(QWidget* box, QFormLayout* form);
// The row, connected to the runner's runOnce, runContinuously and stop.
template <typename Runner>
RunButtons addRunButtons(QWidget* box, QFormLayout* form, Runner* runner) {
    const RunButtons run = addRunButtons(box, form);
    QObject::connect(run.once, &QPushButton::clicked, runner, &Runner::runOnce);
    QObject::connect(run.loop, &QPushButton::clicked, runner, &Runner::runContinuously);
    QObject::connect(run.stop, &QPushButton::clicked, runner, &Runner::stop);
    return run;
}
QLabel* addStatusLine(QWidget* box, QFormLayout* form, const QString& objectName); // word-wrapped

struct RunRow {
    QStringList cells;      // in the columns' order; the first is the run's number
    QList<int> leftAligned; // the text columns; numbers are right-aligned
    QString fault;          // "" or what went wrong: the row is drawn in red with it as the tooltip
};
void appendRun(QTableWidget* runs, const RunRow& row);
int selectedRunNumber(const QTableWidget* runs); // 0 when no row is selected

QString milliseconds(const std::optional<double>& seconds); // "12.5", or a dash when there is none
// "Run 3: overshoot 12.5 %, rise 4.1 ms, settle 20.0 ms."
QString stepSummary(int runNumber, const scope::StepMetrics& metrics);

} // namespace app
