// CaptureTableModel: Scope > View Data — a capture's samples as a read-only table (time, then one column
// per channel with its unit). GUI thread only.
#pragma once

#include "scope/capture.h"

#include <QAbstractTableModel>

namespace app {

class CaptureTableModel final : public QAbstractTableModel {
    Q_OBJECT
public:
    explicit CaptureTableModel(scope::Capture capture, QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

private:
    scope::Capture m_capture;
};

} // namespace app
