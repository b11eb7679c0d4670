// MeasurementsTable: one row per channel of the capture on the scope — min, max, mean, RMS, p-p, and for
// feedback channels overshoot, 10-90 % rise, 2 % settling, steady-state error and following-error peak
// (scope::measure). GUI thread only.
#pragma once

#include "scope/capture.h"

#include <QTableWidget>

namespace app {

class MeasurementsTable final : public QTableWidget {
    Q_OBJECT
public:
    explicit MeasurementsTable(QWidget* parent = nullptr);

    void showMeasurements(const scope::Capture& capture);
    // The text of a cell by row channel name and column title ("VFB", "Rise (ms)"), for tests and tours.
    QString cell(const QString& channel, const QString& column) const;
};

} // namespace app
