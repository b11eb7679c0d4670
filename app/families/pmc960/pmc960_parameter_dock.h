// Pmc960ParameterDock: the PMC-960's variable browser, its parameter table — every parameter of the catalog (motion buffer,
// system registers, the non-volatile T table) with its stored (?) and in-use (!) value read through the
// session, its range and description. The stored value is editable: checked against the catalog's limits
// first, then written (with SW1/SW0 around T-table writes) and read back; a refusal shows the controller's
// #xx code and words. Reads only when asked (Refresh, connect, after a write), never during a transfer.
// GUI thread only.
#pragma once

#include <QDockWidget>
#include <QHash>

class QLabel;
class QLineEdit;
class QPushButton;
class QTableWidget;
class QTableWidgetItem;

namespace serialport {
class Pmc960Session;
struct Pmc960Response;
} // namespace serialport

namespace app {

class Pmc960ParameterDock final : public QDockWidget {
    Q_OBJECT
public:
    enum Column { NameColumn, StoredColumn, InUseColumn, RangeColumn, DescriptionColumn, ColumnCount };

    explicit Pmc960ParameterDock(QWidget* parent = nullptr);

    void setSession(serialport::Pmc960Session* session);
    void setPaused(bool paused);
    // Reads every parameter's stored and in-use value.
    void refresh();
    // Sets a parameter's stored value as if typed into its cell; false when the catalog refuses it at once
    // (the reason is in message()). The controller's answer arrives later (writeFinished).
    bool setStoredValue(const QString& name, const QString& text);

    QTableWidget* table() const { return m_table; }
    // Shows only the rows whose name or description contains text (the search field's text).
    void setFilter(const QString& text);
    int visibleRows() const;
    int rowOf(const QString& name) const;
    QString stored(const QString& name) const;
    QString inUse(const QString& name) const;
    // The last message under the table ("TGP set to 20", "#90 ...: ...", "TGP must lie within 0 - 255").
    QString message() const;
    // Reads still outstanding (0 once a refresh has finished).
    int pendingReads() const { return int(m_reads.size()); }

signals:
    void writeFinished(const QString& name, bool ok);
    void refreshed();

private:
    struct Read {
        int row = 0;
        int column = 0;
    };
    struct Write {
        int row = 0;
        QString text;
    };

    void readRow(int row);
    void onFinished(quint64 id, const serialport::Pmc960Response& response);
    void onFailed(quint64 id, const QString& reason);
    void onItemChanged(QTableWidgetItem* item);
    void setCell(int row, int column, const QString& text);
    void markDifference(int row);
    void showMessage(const QString& text, bool error);

    serialport::Pmc960Session* m_session = nullptr;
    QTableWidget* m_table;
    QLineEdit* m_filter;
    QPushButton* m_refresh;
    QLabel* m_message;
    QHash<quint64, Read> m_reads;
    QHash<quint64, Write> m_writes;
    bool m_updating = false;
    bool m_paused = false;
};

} // namespace app
