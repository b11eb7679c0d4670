// Sc750SetupDataTable: Controller Set Up's "Controller Set Up Data" screen (Manual, L2530-L2553), the
// motor's electrical and mechanical characteristics as an editable table with a range per row. GUI thread.
//
// chosen: the rows are what catalog::sc750::setupParameters reads (Kt, winding R and L, rotor and load
// inertia, poles, continuous and peak current, max speed); the manual names no fields. Continuous current
// is shown for the user's check against the controller (the warning at L2442) and used by no rule.
#pragma once

#include "drive_core/catalog/sc750_motors.h"

#include <QTableWidget>

#include <optional>

namespace app {

class Sc750SetupDataTable final : public QTableWidget {
    Q_OBJECT
public:
    explicit Sc750SetupDataTable(QWidget* parent = nullptr);

    // Shows data (without emitting dataEdited).
    void setSetupData(const drive_core::catalog::sc750::SetupData& data);
    // The values in the table, or nullopt when a cell is not a number in its row's range (the cell turns
    // red and problem() says which; valid cells lose their red). gentle is left false: the System Response is the
    // dialog's.
    std::optional<drive_core::catalog::sc750::SetupData> setupData();
    QString problem() const { return m_problem; }
    // The value cell of the row labelled label ("Load inertia"), or nullptr.
    QTableWidgetItem* valueItem(const QString& label) const;

signals:
    void dataEdited(); // the user changed a value

private:
    bool m_filling = false;
    QString m_problem;
};

} // namespace app
