// TuningPanel: the Tuning dock of every drive family, over its Tuner — the gains (spin box and slider bounded by
// the catalog, or a check box for a switch; each change sent and marked once the drive confirms it; Read from
// Drive), a test move preset with its amplitude (the family's proposal taken once, then kept while gains change)
// and hold, Run Once / Run Continuously / Stop, each run's response overlaid on a scope, a runs table (gains
// changed, overshoot, rise, settling and the family's own columns) with undo to any run's gains, Save Gains where
// the family has a file for them, and the Bode plot of a run's velocity loop. A family adds its own controls
// below (the BDS5's TUNE: families/bds5/tuning/bds5_tuning_controls.h). GUI thread only.
#pragma once

#include "tuner.h"
#include "tuning_frame.h"

#include <QMap>
#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QProgressBar;
class QPushButton;
class QSlider;
class QSpinBox;
class QTableWidget;
class QVBoxLayout;

namespace app {

class BodeView;
class ScopeView;

class TuningPanel final : public QWidget {
    Q_OBJECT
public:
    // Takes the tuner (it becomes the panel's child).
    explicit TuningPanel(Tuner* tuner, QWidget* parent = nullptr);

    Tuner& tuner() { return *m_tuner; }
    // The family's own runner behind the Tuner (TuningRunner, FamilyTuningRunner); asking for another is a bug.
    template <typename Runner>
    Runner& runner() {
        auto* runner = qobject_cast<Runner*>(m_tuner);
        if (!runner) qFatal("TuningPanel::runner: the panel's tuner is a %s", m_tuner->metaObject()->className());
        return *runner;
    }
    ScopeView* view() const { return m_view; }
    QTableWidget* runsTable() const { return m_runsTable; }
    QDoubleSpinBox* gainEditor(const QString& name) const { return m_editors.value(name); } // nullptr: a switch
    QCheckBox* gainSwitch(const QString& name) const { return m_switches.value(name); }
    QString gainMark(const QString& name) const; // "✓", "✗ why", "…" while sent, "" before any answer
    QComboBox* movePreset() const { return m_move; }
    QSpinBox* amplitude() const { return m_amplitude; }
    QSpinBox* hold() const { return m_hold; }
    // Shows a move in the fields and hands it to the tuner; the amplitude is the caller's (no proposal taken).
    void setMove(int index, int amplitude, int holdMs);
    int proposedAmplitude() const { return m_tuner->proposedAmplitude().value_or(0); } // 0 until the drive's values are read
    void useProposedAmplitude(); // Propose: take the proposal (now, or once the drive's values are read)
    QString proposalText() const;
    QString warningText() const; // "" while hidden: "ICMD reached ILIM in run n..."
    QString statusText() const;
    void setStatus(const QString& text);
    // The Bode view of the selected run (the newest when none is selected), opened and raised; it follows
    // the selection and new runs while it is shown.
    BodeView* frequencyResponse();
    void saveGainsAs(); // a file dialog (not blocking), when the family has a gains file
    // A family's own group, added under the test move ("TUNE (self-tuning)").
    void addControls(QWidget* group);

private:
    QWidget* buildGains();
    QWidget* buildTestMove();
    void addGain(QWidget* box, QFormLayout* form, const TuningGain& gain);
    void showGain(const QString& name, double value);
    void markGain(const QString& name, const QString& refusal);
    void applyMove();
    void updateProposal();
    void addRun(const TunerRow& row);
    void updateButtons();
    void showBode();

    Tuner* m_tuner;
    ScopeView* m_view;
    QTableWidget* m_runsTable;
    QVBoxLayout* m_controls = nullptr;
    RunButtons m_run; // the frame: the scope, the runs and the row that starts and stops them
    QMap<QString, QDoubleSpinBox*> m_editors;
    QMap<QString, QSlider*> m_sliders;
    QMap<QString, QCheckBox*> m_switches;
    QMap<QString, QLabel*> m_marks;
    QComboBox* m_move = nullptr;
    QSpinBox* m_amplitude = nullptr;
    QSpinBox* m_hold = nullptr;
    QLabel* m_proposal = nullptr;
    QLabel* m_moveText = nullptr;
    QProgressBar* m_progress = nullptr;
    QLabel* m_status = nullptr;
    QLabel* m_warning = nullptr;
    QPushButton* m_undo = nullptr;
    BodeView* m_bode = nullptr;
    bool m_showing = false;       // the fields change from code (the drive's values, a proposal), not the user
    bool m_followProposal = true; // take the next proposal (then keep it)
};

} // namespace app
