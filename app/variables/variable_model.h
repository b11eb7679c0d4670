// VariableModel: every parameter of a family's catalog (the common schema, drive_core/catalog/drive_catalog.h)
// as a two-level tree (group -> variable) with the last value read from the drive, unit, limits, when it
// is writable and description; the family's VariableRules group it, read its limits and check edits.
// Widget-free: views, the poller and tests share it. An edit of the Value column is checked and handed on
// as editRequested(); the model's value changes only when the drive is read again. GUI thread.
#pragma once

#include "variable_rules.h"

#include <QAbstractItemModel>
#include <QHash>
#include <QStringList>

#include <memory>
#include <vector>

namespace app {

class VariableModel final : public QAbstractItemModel {
    Q_OBJECT
public:
    enum Column { Name, Value, Second, Unit, Limits, Condition, Description, ColumnCount }; // Second: rules
    enum Role { NameRole = Qt::UserRole + 1, PinnedRole, ChangedRole };

    explicit VariableModel(drive_core::DriveFamily family = drive_core::DriveFamily::Bds5, QObject* parent = nullptr);
    ~VariableModel() override;

    const VariableRules& rules() const { return *m_rules; }

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    // The index of a variable ("VMAX", "X12") in the given column; invalid if unknown.
    QModelIndex indexOf(const QString& name, int column = Name) const;
    QStringList groupNames() const;
    // A value as the drive printed it ("7500"); empty until read. A change from a previous read marks the
    // row changed (highlighted) until clearChanged().
    void setValue(const QString& name, const QString& printed);
    QString value(const QString& name) const;
    // The second value the family keeps beside it (VariableRules::secondTitle), as the drive printed it.
    void setSecond(const QString& name, const QString& printed);
    QString second(const QString& name) const;
    std::optional<double> number(const QString& name) const;
    bool isChanged(const QString& name) const;
    void clearChanged();
    // Variables the drive refused to print (ERR on P): shown as such and not polled again.
    void setUnreadable(const QString& name);
    bool isReadable(const QString& name) const;
    void setPinned(const QString& name, bool pinned);
    bool isPinned(const QString& name) const;
    QStringList pinned() const;
    // "NAME value" lines (Motion Link's .VAR) for the given variables that have a value.
    // The names that have a value, each with it (Copy as: the rules make the family's file of them).
    QList<QPair<QString, QString>> namedValues(const QStringList& names) const;
    VariableRules::Context validationContext() const;
    int variableCount() const { return int(m_rows.size()); }

signals:
    // A user's edit passed the checks: send lines ("VMAX 3000") to the drive.
    void editRequested(const QString& name, const QStringList& lines);
    // A user's edit was refused before sending; message names the drive error it would have caused.
    void editRefused(const QString& name, const QString& message);

private:
    struct Row {
        QString name;
        const drive_core::catalog::Parameter* info = nullptr;
        QString value;
        QString second;
        bool changed = false;
        bool pinned = false;
        bool readable = true;
    };
    struct Group {
        QString title;
        std::vector<int> rows; // into m_rows
    };

    const Row* find(const QString& name) const; // nullptr if unknown
    // Sets one field of a row and says so, when the row exists and the field changes.
    template <class T>
    void setField(const QString& name, T Row::*field, const T& to);
    QVariant rowData(const Row& row, int column, int role) const;
    QString displayValue(const Row& row) const;
    void rowChanged(int rowIndex);

    std::unique_ptr<VariableRules> m_rules;
    std::vector<Row> m_rows;
    std::vector<Group> m_groups;
    std::vector<int> m_groupOfRow;
    std::vector<int> m_positionInGroup;
    QHash<QString, int> m_byName;
};

} // namespace app
