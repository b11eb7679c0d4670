// The frame every family's Tuning dock shares (the BDS5's TuningPanel and the SC750's and PMC-960's
// FamilyTuningPanel): the controls scrolled on the left; on the right the scope over the runs table and its
// buttons. The runs table: one read-only row per run, whole rows selected, the run's number first, its gains
// changed second, and its measurements. GUI thread only.
#pragma once

#include <QList>
#include <QString>
#include <QStringList>

#include <optional>

class QFormLayout;
class QLabel;
class QPushButton;
class QTableWidget;
class QWidget;

namespace app {

class ScopeView;

// Lays `controls`, `view`, `runs` and the buttons under it into `panel` (which gets the layout).
void layOutTuningFrame(QWidget* panel, QWidget* controls, ScopeView* view, QTableWidget* runs,
                       const QList<QPushButton*>& runButtons);
void setUpRunsTable(QTableWidget* runs, const QStringList& columns);

// The test move's Run Once / Run Continuously / Stop row, added to its form.
struct RunButtons {
    QPushButton* once = nullptr;
    QPushButton* loop = nullptr;
    QPushButton* stop = nullptr;
};
RunButtons addRunButtons(QWidget* box, QFormLayout* form);
QLabel* addStatusLine(QWidget* box, QFormLayout* form, const QString& objectName); // word-wrapped

struct RunRow {
    QStringList cells;      // in the columns' order; the first is the run's number
    QList<int> leftAligned; // the text columns; numbers are right-aligned
    QString fault;          // "" or what went wrong: the row is drawn in red with it as the tooltip
};
void appendRun(QTableWidget* runs, const RunRow& row);
int selectedRunNumber(const QTableWidget* runs); // 0 when no row is selected

QString milliseconds(const std::optional<double>& seconds); // "12.5", or a dash when there is none

} // namespace app
