// ErrorLogModel: the rows of the error log — the drive's ERR HIST and the errors it reported while we
// watched — each with its severity (App. D, Table D.1), the catalog's text and what the manual says to do.
// Widget-free (icons come from the style). GUI thread.
#pragma once

#include "serialport/bds5_protocol.h"

#include "drive_core/catalog/bds5_catalog.h"

#include <QAbstractTableModel>
#include <QDateTime>

#include <vector>

namespace app {

class ErrorLogModel final : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Severity, Code, Message, Line, Source, Hint, ColumnCount };
    enum Role { ProgramLineRole = Qt::UserRole + 1, SeverityRole };
    enum class Origin { History, Reported };

    struct Entry {
        serialport::Bds5ErrorLine error;
        Origin origin = Origin::Reported;
        int historyPosition = 0; // 1 = newest in ERR HIST
        QDateTime seen;          // when reported (Reported only)
    };

    using QAbstractTableModel::QAbstractTableModel;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    // Replaces the history rows (the drive's ERR HIST, newest first); reported rows stay, above them.
    void setHistory(const QList<serialport::Bds5ErrorLine>& history);
    void addReported(const serialport::Bds5ErrorLine& error, const QDateTime& when);
    void clear();
    const Entry& entry(int row) const { return m_entries[std::size_t(row)]; }

    static QString severityName(drive_core::catalog::bds5::Severity severity);
    static QString fixHint(int code);
    // One CSV line per row, with a header: severity, code, message, line, entry, source, hint.
    QString toCsv() const;

private:
    std::vector<Entry> m_entries; // reported (newest first), then history (newest first)
};

} // namespace app
