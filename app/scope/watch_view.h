// WatchView: Scope > Watch Variables — a chooser of the family's values, Start/Stop, and the polled rolling
// chart of the last 30 s labelled with its measured sample rate. The polling is VariableWatcher's, the
// reading the family's WatchSource (which the view owns). One per family. GUI thread only.
// With a trigger set (TriggerBar, WatchTrigger) the chart holds the last triggered frame instead, its time
// counted from the trigger instant, which a vertical line marks (and the level a horizontal one).
#pragma once

#include <QDialog>

class QCPItemStraightLine;
class QCPItemText;
class QCustomPlot;
class QLabel;
class QListWidget;
class QPushButton;

namespace scope {
struct TriggerFrame;
}

namespace app {

class TriggerBar;
class VariableWatcher;
class WatchSource;
class WatchTrigger;

class WatchView final : public QDialog {
    Q_OBJECT
public:
    // Takes ownership of source.
    WatchView(WatchSource* source, QWidget* parent = nullptr);

    VariableWatcher& watcher() { return *m_watcher; }
    WatchTrigger& trigger() { return *m_trigger; }
    TriggerBar* triggerBar() const { return m_triggerBar; }
    QCustomPlot* plot() const { return m_plot; }
    QString rateLabel() const;
    QListWidget* chooser() const { return m_chooser; }
    // Ticks the named variables in the chooser (1 to 4) and starts watching them.
    void watch(const QStringList& names);
    void start(); // the ticked variables
    void stop();

private:
    void onSampled(double time_s);
    void updateState();
    void onTriggerSettings();
    void arm();
    void showFrame(const scope::TriggerFrame& frame);
    void showRolling();
    void fitValueAxes();

    VariableWatcher* m_watcher;
    QListWidget* m_chooser;
    QPushButton* m_start;
    QPushButton* m_stop;
    QLabel* m_rate;
    QCustomPlot* m_plot;
    TriggerBar* m_triggerBar;
    WatchTrigger* m_trigger;
    QCPItemStraightLine* m_triggerLine; // at the trigger instant, x = 0, while a frame shows
    QCPItemStraightLine* m_levelLine;   // at the level, on the source's axis
    QCPItemText* m_triggerMark;
    double m_plottedUntil_s = -1; // samples up to this time are in the graphs already
    bool m_frameShown = false;    // the graphs hold a triggered frame, not the rolling window
};

} // namespace app
