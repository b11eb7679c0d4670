// RecordDialog: Scope > From Drive's set-up — 1 to 4 recordable variables from the catalog, the interval
// (1 ms .. 60 s) and the number of samples limited as the manual says (1000/500/333/250), an optional
// trigger sent right after RECORD (J 1000) and an optional command to end the move later (J 0 after T ms).
// Non-modal; the caller reads plan() on accepted(). GUI thread only.
#pragma once

#include "serialport/bds5_record_play.h"

#include <QDialog>

class QComboBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace app {

class RecordDialog final : public QDialog {
    Q_OBJECT
public:
    explicit RecordDialog(QWidget* parent = nullptr);

    serialport::Bds5RecordPlan plan() const;
    void setPlan(const serialport::Bds5RecordPlan& plan);

private:
    void updateLimits();

    QComboBox* m_variables[4];
    QSpinBox* m_samples;
    QSpinBox* m_interval;
    QLineEdit* m_trigger;
    QLineEdit* m_then;
    QSpinBox* m_thenAt;
    QLabel* m_summary;
};

} // namespace app
