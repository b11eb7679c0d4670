// GainEditor: one tuning gain as a spin box and a slider bounded by the catalog's limits (a check box for
// a switch), with a mark showing whether the drive confirmed the value. Emits edited() once per change
// (Enter, arrows, slider release), never per keystroke. GUI thread only.
#pragma once

#include "families/bds5/record/scope_catalog.h"

#include <QWidget>

class QCheckBox;
class QLabel;
class QSlider;
class QSpinBox;

namespace app {

class GainEditor final : public QWidget {
    Q_OBJECT
public:
    GainEditor(const GainInfo& info, QWidget* parent = nullptr);

    const GainInfo& info() const { return m_info; }
    int value() const;
    // Shows a value without emitting edited() (a read from the drive, an undo).
    void setValue(int value);
    void setConfirmed(bool confirmed, const QString& why = {});
    QSpinBox* spinBox() const { return m_spin; }

signals:
    void edited(const QString& name, int value);

private:
    GainInfo m_info;
    QSpinBox* m_spin = nullptr;
    QSlider* m_slider = nullptr;
    QCheckBox* m_check = nullptr;
    QLabel* m_mark;
};

} // namespace app
