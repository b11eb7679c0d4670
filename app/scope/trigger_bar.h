// TriggerBar: the trigger controls of Watch Variables, as on an oscilloscope — mode (Off: the rolling chart;
// Single, Normal, Auto), source channel, level or edge, slope, level (or an edge's least step), pre-trigger %,
// frame length in samples, an Arm button and the state ("Armed", "Waiting", "Triggered", "Auto", "Stopped").
// Only the controls; WatchTrigger does the triggering. GUI thread only.
#pragma once

#include "scope/trigger.h"

#include <QWidget>

#include <optional>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace app {

class TriggerBar final : public QWidget {
    Q_OBJECT
public:
    explicit TriggerBar(QWidget* parent = nullptr);

    // The settings shown, or nullopt when the mode is Off (no trigger: the rolling chart).
    std::optional<scope::TriggerSettings> settings() const;
    // The channels a trigger can take its source from, in the watcher's order; keeps the choice if it stays.
    void setSources(const QStringList& labels);
    void setState(const QString& text);
    QString stateText() const;
    QPushButton* armButton() const { return m_arm; }

    // As a user would set them (tests, the tour); each emits settingsChanged().
    void setMode(std::optional<scope::TriggerMode> mode);
    void setSource(int channel);
    void setKind(scope::TriggerKind kind);
    void setSlope(scope::TriggerSlope slope);
    void setLevel(double level);
    void setPreTrigger(double pct);
    void setFrameSamples(int samples);

signals:
    void settingsChanged();
    void armClicked();

private:
    void updateFields();

    QComboBox* m_mode;
    QComboBox* m_source;
    QComboBox* m_kind;
    QComboBox* m_slope;
    QLabel* m_levelLabel;
    QDoubleSpinBox* m_level;
    QDoubleSpinBox* m_pre;
    QSpinBox* m_frame;
    QPushButton* m_arm;
    QLabel* m_state;
};

} // namespace app
