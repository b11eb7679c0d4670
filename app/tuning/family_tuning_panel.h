// FamilyTuningPanel: the Tuning dock of the SC750 and the PMC-960 — the profile's gains (spin boxes bounded by
// the catalog, each change sent and confirmed, Read from Drive), a test move preset with its amplitude and
// hold, Run Once / Run Continuously / Stop, each run's response overlaid on a scope with its measurements, a
// runs table (gains changed, overshoot, rise, settling, what was sampled) with undo to any run's gains, and
// the Bode plot of a run's velocity loop (the bench's command probe against its monitor output). The drive
// work is FamilyTuningRunner's; the workspace attaches its session. GUI thread only.
#pragma once

#include "family_tuning_runner.h"
#include "tuning_frame.h"

#include <QMap>
#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace app {

class BodeView;
class ScopeView;

class FamilyTuningPanel final : public QWidget {
    Q_OBJECT
public:
    explicit FamilyTuningPanel(TuningProfile profile, QWidget* parent = nullptr);

    // The workspace's connection (nullptr, nullptr when none); the gains are read once it is there.
    void attach(serialport::DriveSession* session, serialport::Link* link);

    FamilyTuningRunner& runner() { return *m_runner; }
    ScopeView* view() const { return m_view; }
    QTableWidget* runsTable() const { return m_runsTable; }
    QDoubleSpinBox* gainEditor(const QString& name) const { return m_editors.value(name); }
    QString gainMark(const QString& name) const; // "✓", "✗ why" or "" while unconfirmed
    QComboBox* movePreset() const { return m_move; }
    QSpinBox* amplitude() const { return m_amplitude; }
    QSpinBox* hold() const { return m_hold; }
    QString statusText() const;
    // The Bode view of the selected run (the newest when none is selected), opened and raised; it follows
    // the selection and new runs while it is shown.
    BodeView* frequencyResponse();

private:
    QWidget* buildGains();
    QWidget* buildTestMove();
    void applyMove();
    void addRun(const FamilyTuningRun& run);
    void updateButtons();
    void showBode();
    void setStatus(const QString& text);
    void showGain(const QString& name, double value, const QString& mark);

    FamilyTuningRunner* m_runner;
    ScopeView* m_view;
    QTableWidget* m_runsTable;
    RunButtons m_run; // the frame: the scope, the runs and the row that starts and stops them
    QMap<QString, QDoubleSpinBox*> m_editors;
    QMap<QString, QLabel*> m_marks;
    QComboBox* m_move = nullptr;
    QSpinBox* m_amplitude = nullptr;
    QSpinBox* m_hold = nullptr;
    QLabel* m_moveText = nullptr;
    QPushButton* m_undo = nullptr;
    QPushButton* m_bodeButton = nullptr;
    BodeView* m_bode = nullptr;
    QLabel* m_status = nullptr;
    bool m_showing = false; // setting an editor from the drive: not an edit
};

} // namespace app
