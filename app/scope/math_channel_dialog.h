// MathChannelDialog: Scope > Math... — pick an operation (A + B, A - B, k A, d/dt, integral, moving average,
// following error) and its operands among the channels shown, see the new channel's name and unit (or why it
// cannot be made: units that differ, no room on the plot) before adding it. GUI thread only.
#pragma once

#include "scope/capture.h"
#include "scope/math_channel.h"

#include <QDialog>

class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;

namespace app {

class MathChannelDialog final : public QDialog {
    Q_OBJECT
public:
    // shown: the capture the scope shows now, math channels included; room: channels the plot can still take.
    MathChannelDialog(const scope::Capture& shown, int room, QWidget* parent = nullptr);

    // What the user chose; name set to the one the preview shows. Valid when canAdd().
    scope::MathChannelSpec spec() const;
    bool canAdd() const;
    // "Adds d/dt(VFB) [VEL/s]" or why not, as the dialog shows it.
    QString preview() const;

    // For tests and the tour: choose as a user would in the combo boxes.
    void choose(scope::MathOp op, const QString& a, const QString& b = {});
    void setFactor(double k);
    void setWindow(int samples);

private:
    void updateFields();
    void updatePreview();

    scope::Capture m_shown;
    int m_room;
    QComboBox* m_op;
    QComboBox* m_a;
    QComboBox* m_b;
    QDoubleSpinBox* m_k;
    QLineEdit* m_unit;
    QSpinBox* m_window;
    QFormLayout* m_form;
    QLabel* m_preview;
    QPushButton* m_add;
    scope::MathChannelSpec m_spec; // the last one previewed
    bool m_ok = false;
};

} // namespace app
