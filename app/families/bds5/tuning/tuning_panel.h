// TuningPanel: the Tuning dock — gains (spin boxes + sliders bounded by the catalog, each change sent and
// confirmed), a test move preset with an amplitude proposed from the drive's values, Run once / Run continuously /
// Stop (asking first when the move would pass the soft limits), the runs' overlays on a scope with measurements, a
// per-run table (overshoot, rise, settle, cycle time) with undo to any run's gains and Save .VAR, and TUNE with the
// manual's warning. The drive work is TuningRunner's. GUI thread only.
#pragma once

#include "tuning/tuning_frame.h"
#include "tuning_runner.h"

#include <QMap>
#include <QPointer>
#include <QWidget>

class QComboBox;
class QLabel;
class QMessageBox;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace app {

class GainEditor;
class MainWindow;
class ScopeView;

class TuningPanel final : public QWidget {
    Q_OBJECT
public:
    TuningPanel(MainWindow& window, QWidget* parent = nullptr);

    TuningRunner& runner() { return *m_runner; }
    ScopeView* view() const { return m_view; }
    QTableWidget* runsTable() const { return m_runsTable; }
    GainEditor* gainEditor(const QString& name) const { return m_editors.value(name); }
    QString statusText() const;
    // Shows the preset in the test-move fields and hands it to the runner; the amplitude is the caller's.
    void setTestMove(const TestMove& move);
    // The amplitude proposed for the chosen preset from the drive's values (TestMove::proposedAmplitude). The
    // Amplitude field takes it once — when the drive's values are first read, on Propose, when the user picks a
    // preset — and then keeps it (and the position step's speed) while gains change: the runs' overlays compare
    // one move. Only the "Proposed:" line follows the gains.
    int proposedAmplitude() const;
    void useProposedAmplitude();
    QString proposalText() const;
    QString warningText() const; // empty while hidden: "ICMD reached ILIM in run n..."
    // The question shown (non-modal) while a run waits because its move would pass PMAX/PMIN: "Turn off the
    // soft limits (PLIM=0) for the test" or Cancel. nullptr when none is open.
    QMessageBox* softLimitsQuestion() const;
    void saveGainsAs();

private:
    QWidget* buildGains();
    QWidget* buildTestMove();
    QWidget* buildTune();
    void applyTestMove();
    void updateProposal();
    void askAboutSoftLimits(const QString& why);
    TestMove::DriveValues proposalValues() const;
    void addRun(const TuningRun& run);
    void updateButtons();
    void setStatus(const QString& text);

    MainWindow& m_window;
    TuningRunner* m_runner;
    QMap<QString, GainEditor*> m_editors;
    ScopeView* m_view;
    QTableWidget* m_runsTable;
    RunButtons m_run; // the frame: the scope, the runs and the row that starts and stops them
    QComboBox* m_moveKind = nullptr;
    QSpinBox* m_amplitude = nullptr;
    QSpinBox* m_duration = nullptr;
    QComboBox* m_bandwidth = nullptr;
    QComboBox* m_stability = nullptr;
    QPushButton* m_undo = nullptr;
    QProgressBar* m_progress = nullptr;
    QLabel* m_status = nullptr;
    QLabel* m_warning = nullptr;
    QLabel* m_proposal = nullptr;
    bool m_followProposal = true; // take the next proposal (then keep it)
    int m_moveVelocity = 0;       // the position step's MI speed, proposed with the amplitude; 0: VDEFAULT
    QPointer<QMessageBox> m_limitsQuestion;
    bool m_settingFields = false; // the fields change from code, not from the user
};

} // namespace app
