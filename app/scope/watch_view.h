// WatchView: Scope > Watch Variables — a chooser of the family's values, Start/Stop, and the polled rolling
// chart of the last 30 s labelled with its measured sample rate. The polling is VariableWatcher's, the
// reading the family's WatchSource (which the view owns). One per family. GUI thread only.
#pragma once

#include <QDialog>

class QCustomPlot;
class QLabel;
class QListWidget;
class QPushButton;

namespace app {

class VariableWatcher;
class WatchSource;

class WatchView final : public QDialog {
    Q_OBJECT
public:
    // Takes ownership of source.
    WatchView(WatchSource* source, QWidget* parent = nullptr);

    VariableWatcher& watcher() { return *m_watcher; }
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

    VariableWatcher* m_watcher;
    QListWidget* m_chooser;
    QPushButton* m_start;
    QPushButton* m_stop;
    QLabel* m_rate;
    QCustomPlot* m_plot;
    double m_plottedUntil_s = -1; // samples up to this time are in the graphs already
};

} // namespace app
