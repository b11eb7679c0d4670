// Sc750SetupDataTable: the set-up data rows, their ranges, and reading them back.
#include "sc750_setup_data_table.h"

#include <QBrush>
#include <QHeaderView>

#include <cmath>

namespace app {

namespace catalog = drive_core::catalog::sc750;

namespace {
// One row: label, unit, accepted range (chosen: wide enough for any servo the SC750 family drives), and
// how it maps to SetupData.
struct Row {
    const char* label;
    const char* unit;
    double min;
    double max;
    bool evenInteger;
    double (*get)(const catalog::SetupData&);
    void (*set)(catalog::SetupData&, double);
};

// clang-format off
const Row kRows[] = {
    {"Torque constant (Kt)", "N·m/A", 0.01, 20, false, [](const catalog::SetupData& d) { return d.torqueConstant_NmPerA; }, [](catalog::SetupData& d, double v) { d.torqueConstant_NmPerA = v; }},
    {"Winding resistance", "Ω", 0.01, 100, false, [](const catalog::SetupData& d) { return d.resistance_ohm; }, [](catalog::SetupData& d, double v) { d.resistance_ohm = v; }},
    {"Winding inductance", "mH", 0.01, 500, false, [](const catalog::SetupData& d) { return d.inductance_mH; }, [](catalog::SetupData& d, double v) { d.inductance_mH = v; }},
    {"Rotor inertia", "kg·cm²", 0.001, 1000, false, [](const catalog::SetupData& d) { return d.rotorInertia_kgcm2; }, [](catalog::SetupData& d, double v) { d.rotorInertia_kgcm2 = v; }},
    {"Load inertia", "kg·cm²", 0, 100000, false, [](const catalog::SetupData& d) { return d.loadInertia_kgcm2; }, [](catalog::SetupData& d, double v) { d.loadInertia_kgcm2 = v; }},
    {"Pole count", "", 2, 48, true, [](const catalog::SetupData& d) { return double(d.poleCount); }, [](catalog::SetupData& d, double v) { d.poleCount = int(v); }},
    {"Continuous current", "A RMS", 0.1, 200, false, [](const catalog::SetupData& d) { return d.continuous_A; }, [](catalog::SetupData& d, double v) { d.continuous_A = v; }},
    {"Peak current", "A RMS", 0.1, 600, false, [](const catalog::SetupData& d) { return d.peak_A; }, [](catalog::SetupData& d, double v) { d.peak_A = v; }},
    {"Maximum speed", "rpm", 10, 20000, false, [](const catalog::SetupData& d) { return d.maxSpeed_rpm; }, [](catalog::SetupData& d, double v) { d.maxSpeed_rpm = v; }},
};
// clang-format on
constexpr int kValueColumn = 1;
} // namespace

Sc750SetupDataTable::Sc750SetupDataTable(QWidget* parent) : QTableWidget(int(std::size(kRows)), 3, parent) {
    setObjectName(QStringLiteral("sc750SetupData"));
    setHorizontalHeaderLabels({tr("Characteristic"), tr("Value"), tr("Unit")});
    verticalHeader()->hide();
    horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    horizontalHeader()->setSectionResizeMode(2, QHeaderView::ResizeToContents);
    horizontalHeader()->setSectionResizeMode(1, QHeaderView::Stretch);
    // All nine rows in view: the screen is read as a whole (the manual's is one page).
    verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 8);
    setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
    setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    for (int row = 0; row < rowCount(); ++row) {
        for (int column : {0, 2}) {
            auto* item = new QTableWidgetItem(column == 0 ? tr(kRows[row].label) : QString::fromUtf8(kRows[row].unit));
            item->setFlags(item->flags() & ~Qt::ItemIsEditable);
            setItem(row, column, item);
        }
        setItem(row, kValueColumn, new QTableWidgetItem);
    }
    connect(this, &QTableWidget::itemChanged, this, [this](QTableWidgetItem* item) {
        if (!m_filling && item->column() == kValueColumn) emit dataEdited();
    });
}

void Sc750SetupDataTable::setSetupData(const catalog::SetupData& setup) {
    m_filling = true;
    for (int row = 0; row < rowCount(); ++row) {
        item(row, kValueColumn)->setText(QString::number(kRows[row].get(setup), 'g', 9));
        item(row, kValueColumn)->setBackground(QBrush());
    }
    m_filling = false;
}

std::optional<catalog::SetupData> Sc750SetupDataTable::setupData() {
    catalog::SetupData setup;
    m_problem.clear();
    for (int row = 0; row < rowCount(); ++row) {
        QTableWidgetItem* cell = item(row, kValueColumn);
        bool ok = false;
        const double value = cell->text().trimmed().toDouble(&ok);
        const Row& r = kRows[row];
        const bool integer = r.evenInteger;
        const bool valid = ok && value >= r.min && value <= r.max && (!integer || std::fmod(value, 2) == 0);
        cell->setBackground(valid ? QBrush() : QBrush(QColor(0xf9, 0xde, 0xdc)));
        if (valid)
            r.set(setup, value);
        else if (m_problem.isEmpty())
            m_problem =
                integer ? tr("%1 must be an even whole number from %2 to %3.").arg(tr(r.label)).arg(r.min).arg(r.max)
                        : tr("%1 must be a number from %2 to %3 %4.")
                              .arg(tr(r.label))
                              .arg(r.min)
                              .arg(r.max)
                              .arg(QString::fromUtf8(r.unit));
    }
    if (!m_problem.isEmpty()) return std::nullopt;
    return setup;
}

QTableWidgetItem* Sc750SetupDataTable::valueItem(const QString& label) const {
    for (int row = 0; row < rowCount(); ++row)
        if (item(row, 0)->text() == label) return item(row, kValueColumn);
    return nullptr;
}

} // namespace app
