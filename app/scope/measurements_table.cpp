// MeasurementsTable: scope::measure() as a table.
#include "measurements_table.h"

#include "scope/capture_measurements.h"

#include <QHeaderView>

namespace app {

namespace {
const QStringList kColumns = {QStringLiteral("Channel"),     QStringLiteral("Min"),       QStringLiteral("Max"),
                              QStringLiteral("Mean"),        QStringLiteral("RMS"),       QStringLiteral("p-p"),
                              QStringLiteral("Overshoot %"), QStringLiteral("Rise (ms)"), QStringLiteral("Settle (ms)"),
                              QStringLiteral("SS error"),    QStringLiteral("FE peak")};

QString number(double v) {
    return std::abs(v - std::round(v)) < 1e-9 ? QString::number(qint64(std::llround(v))) : QString::number(v, 'f', 2);
}

QString ms(const std::optional<double>& seconds) {
    return seconds ? QString::number(*seconds * 1000, 'f', 1) : QStringLiteral("\u2014");
}
} // namespace

MeasurementsTable::MeasurementsTable(QWidget* parent) : QTableWidget(parent) {
    setObjectName(QStringLiteral("measurementsTable"));
    setColumnCount(int(kColumns.size()));
    setHorizontalHeaderLabels(kColumns);
    verticalHeader()->hide();
    // Each column as wide as its header and values; a narrow dock scrolls rather than clip "Overshoot %"
    // to "ershoot" (issue 19, item 11).
    horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    horizontalHeader()->setStretchLastSection(true);
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    setSelectionBehavior(QAbstractItemView::SelectRows);
    setAlternatingRowColors(true);
}

void MeasurementsTable::showMeasurements(const scope::Capture& capture) {
    const auto rows = scope::measure(capture);
    setRowCount(int(rows.size()));
    for (int r = 0; r < int(rows.size()); ++r) {
        const scope::ChannelMeasurements& m = rows[std::size_t(r)];
        const QString unit = m.unit.empty() ? QString() : QStringLiteral(" [%1]").arg(QString::fromStdString(m.unit));
        QStringList cells = {QString::fromStdString(m.name) + unit,
                             number(m.stats.minimum),
                             number(m.stats.maximum),
                             number(m.stats.mean),
                             number(m.stats.rms),
                             number(m.stats.peakToPeak)};
        const QString none = QStringLiteral("\u2014");
        if (m.step && m.step->hasStep) {
            cells << QString::number(m.step->overshoot_pct, 'f', 1) << ms(m.step->rise_s) << ms(m.step->settling_s)
                  << (m.step->steadyStateError ? number(*m.step->steadyStateError) : none)
                  << (m.step->followingErrorPeak ? number(*m.step->followingErrorPeak) : none);
        } else {
            cells << none << none << none << none << none;
        }
        for (int c = 0; c < int(cells.size()); ++c) {
            auto* item = new QTableWidgetItem(cells[c]);
            item->setTextAlignment(c == 0 ? Qt::AlignLeft | Qt::AlignVCenter : Qt::AlignRight | Qt::AlignVCenter);
            if (c == 0) item->setData(Qt::UserRole, QString::fromStdString(m.name));
            setItem(r, c, item);
        }
    }
}

QString MeasurementsTable::cell(const QString& channel, const QString& column) const {
    const int c = int(kColumns.indexOf(column));
    for (int r = 0; r < rowCount() && c >= 0; ++r)
        if (item(r, 0) && item(r, 0)->data(Qt::UserRole).toString() == channel) return item(r, c)->text();
    return {};
}

} // namespace app
