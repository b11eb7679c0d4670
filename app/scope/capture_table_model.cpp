// CaptureTableModel: rows are samples.
#include "capture_table_model.h"

namespace app {

CaptureTableModel::CaptureTableModel(scope::Capture capture, QObject* parent)
    : QAbstractTableModel(parent), m_capture(std::move(capture)) {}

int CaptureTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_capture.sampleCount());
}

int CaptureTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_capture.channels.size()) + 1;
}

QVariant CaptureTableModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid()) return {};
    if (role == Qt::TextAlignmentRole) return int(Qt::AlignRight | Qt::AlignVCenter);
    if (role != Qt::DisplayRole) return {};
    const auto row = std::size_t(index.row());
    if (index.column() == 0) return QString::number(m_capture.timeAt(row) * 1000, 'f', 1);
    const double v = m_capture.channels[std::size_t(index.column() - 1)].values[row];
    return std::abs(v - std::round(v)) < 1e-9 ? QString::number(qint64(std::llround(v))) : QString::number(v, 'f', 3);
}

QVariant CaptureTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (role != Qt::DisplayRole) return {};
    if (orientation == Qt::Vertical) return section + 1;
    if (section == 0) return tr("Time (ms)");
    const scope::CaptureChannel& c = m_capture.channels[std::size_t(section - 1)];
    return c.unit.empty()
               ? QString::fromStdString(c.name)
               : QStringLiteral("%1 (%2)").arg(QString::fromStdString(c.name), QString::fromStdString(c.unit));
}

} // namespace app
