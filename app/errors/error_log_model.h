// ErrorLogModel: the rows of the error log for one drive family — the drive's own record (BDS5 ERR HIST,
// the SC750's FAULTCODE, the PMC-960's `&` error snapshot) and the errors it reported while we watched —
// each with the family's severity word, the catalog's text and what the manual says to do. Rows are
// family-neutral entries; the family's error source fills them in (bds5_error_text.h and the like).
// Widget-free (icons come from the style). GUI thread.
#pragma once

#include "drive_core/drive.h"

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
    // How bad, for the icon and colour; the words shown are the family's (Entry::severity).
    enum class Level { Info, Warning, Error, Fault, Firmware };

    struct Entry {
        drive_core::DriveFamily family = drive_core::DriveFamily::Bds5;
        int code = 0;     // the number: BDS5 ERR n, SC750 FAULTCODE, PMC-960 #xx value; 0 for none
        QString codeText; // as the drive shows it: "92", "F 4", "#9C"
        QString message;  // the drive's or the catalog's words
        QString detail;   // what it was near: the BDS5 entry, the PMC-960 command; shown quoted
        QString severity; // the family's word: "Break", "Fault", "Refused"
        Level level = Level::Error;
        QString hint;        // what to do
        QString explanation; // the tool tip: the manual's meaning and where it says so
        int programLine = 0; // 1-based, as the drive counts; 0 when the error cites none
        Origin origin = Origin::Reported;
        int historyPosition = 0; // 1 = newest in the drive's record
        QString where;           // Source column for history rows, instead of "history #n" ("FAULTCODE")
        QDateTime seen;          // when reported (Reported only)
    };

    explicit ErrorLogModel(drive_core::DriveFamily family, QObject* parent = nullptr)
        : QAbstractTableModel(parent), m_family(family) {}

    drive_core::DriveFamily family() const { return m_family; }
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    // Replaces the history rows (the drive's record, newest first); reported rows stay, above them.
    void setHistory(std::vector<Entry> history);
    // A reported error, newest on top.
    void addReported(Entry entry, const QDateTime& when);
    void clear();
    const Entry& entry(int row) const { return m_entries[std::size_t(row)]; }

    // One CSV line per row, with a header: severity, code, message, line, entry, source, hint.
    QString toCsv() const;

private:
    drive_core::DriveFamily m_family;
    std::vector<Entry> m_entries; // reported (newest first), then history (newest first)
};

} // namespace app
