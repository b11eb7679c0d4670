// VariableModel: the catalog as a tree, with the values the poller reads.
#include "variable_model.h"

#include <QBrush>
#include <QColor>
#include <QFont>

namespace app {

namespace cat = drive_core::catalog;

namespace {
constexpr quintptr kGroupId = 0; // internalId of a group row; a variable's is its group + 1

QString text(std::string_view view) {
    return QString::fromLatin1(view.data(), qsizetype(view.size()));
}

QString conditionText(cat::Writable writable) {
    switch (writable) {
    case cat::Writable::Always: return VariableModel::tr("any time");
    case cat::Writable::WhenDisabled: return VariableModel::tr("drive disabled");
    case cat::Writable::WhenStopped: return VariableModel::tr("no motion");
    case cat::Writable::Never: return VariableModel::tr("read only");
    case cat::Writable::Factory: return VariableModel::tr("factory");
    }
    return {};
}
} // namespace

VariableModel::VariableModel(drive_core::DriveFamily family, QObject* parent)
    : QAbstractItemModel(parent), m_rules(VariableRules::make(family)) {
    const auto all = cat::parameters(family);
    QStringList order = m_rules->groupOrder();
    const bool every = order.isEmpty();
    if (every)
        for (const cat::Parameter& p : all)
            if (const QString g = m_rules->groupOf(p); !order.contains(g)) order << g;
    for (const QString& title : order) {
        Group g{title, {}};
        for (const cat::Parameter& info : all) {
            if (m_rules->groupOf(info) != title) continue;
            const QString stem = text(info.name);
            for (int i = info.firstIndex; i <= info.lastIndex; ++i) {
                Row row{i == 0 ? stem : stem + QString::number(i), &info};
                m_byName.insert(row.name, int(m_rows.size()));
                g.rows.push_back(int(m_rows.size()));
                m_groupOfRow.push_back(int(m_groups.size()));
                m_positionInGroup.push_back(int(g.rows.size()) - 1);
                m_rows.push_back(std::move(row));
            }
        }
        if (!g.rows.empty()) m_groups.push_back(std::move(g));
    }
}

VariableModel::~VariableModel() = default;

QModelIndex VariableModel::index(int row, int column, const QModelIndex& parent) const {
    if (column < 0 || column >= ColumnCount || row < 0) return {};
    if (!parent.isValid()) return row < int(m_groups.size()) ? createIndex(row, column, kGroupId) : QModelIndex();
    if (parent.internalId() != kGroupId) return {};
    const Group& g = m_groups[std::size_t(parent.row())];
    return row < int(g.rows.size()) ? createIndex(row, column, quintptr(parent.row()) + 1) : QModelIndex();
}

QModelIndex VariableModel::parent(const QModelIndex& child) const {
    if (!child.isValid() || child.internalId() == kGroupId) return {};
    return createIndex(int(child.internalId() - 1), 0, kGroupId);
}

int VariableModel::rowCount(const QModelIndex& parent) const {
    if (!parent.isValid()) return int(m_groups.size());
    if (parent.internalId() != kGroupId || parent.column() != 0) return 0;
    return int(m_groups[std::size_t(parent.row())].rows.size());
}

int VariableModel::columnCount(const QModelIndex&) const {
    return ColumnCount;
}

QVariant VariableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
    case Name: return tr("Variable");
    case Value: return m_rules->valueTitle();
    case Second: return m_rules->secondTitle();
    case Unit: return tr("Unit");
    case Limits: return tr("Limits");
    case Condition: return tr("Writable");
    case Description: return tr("Description");
    default: return {};
    }
}

QVariant VariableModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid()) return {};
    if (index.internalId() == kGroupId) {
        const Group& g = m_groups[std::size_t(index.row())];
        if (role == Qt::DisplayRole && index.column() == Name)
            return QStringLiteral("%1 (%2)").arg(g.title).arg(g.rows.size());
        if (role == Qt::FontRole) {
            QFont bold;
            bold.setBold(true);
            return bold;
        }
        return {};
    }
    const Group& g = m_groups[std::size_t(index.internalId() - 1)];
    return rowData(m_rows[std::size_t(g.rows[std::size_t(index.row())])], index.column(), role);
}

QVariant VariableModel::rowData(const Row& row, int column, int role) const {
    switch (role) {
    case NameRole: return row.name;
    case PinnedRole: return row.pinned ? QStringLiteral("pinned") : QString();
    case ChangedRole: return row.changed;
    case Qt::ToolTipRole:
        return text(row.info->description) + QStringLiteral(" (%1)").arg(text(row.info->manualLines)) +
               (row.info->chosen ? tr("; range chosen: the manual gives none") : QString());
    case Qt::BackgroundRole:
        if (column == Second && !row.second.isEmpty() && !row.value.isEmpty() && row.second != row.value)
            return QBrush(QColor(0xff, 0xf4, 0xce)); // in use differs from stored
        return row.changed && column == Value ? QVariant(QBrush(QColor(0xff, 0xe0, 0x82))) : QVariant();
    case Qt::ForegroundRole:
        if (column == Value && !row.readable) return QBrush(QColor(0x9e, 0x9e, 0x9e));
        return column == Condition || column == Limits || column == Unit ? QVariant(QBrush(QColor(0x5f, 0x63, 0x68)))
                                                                         : QVariant();
    case Qt::FontRole:
        if (column == Name || column == Value) {
            QFont font(QStringLiteral("monospace"));
            font.setStyleHint(QFont::Monospace);
            font.setBold(column == Name && row.pinned);
            return font;
        }
        return {};
    case Qt::TextAlignmentRole:
        return column == Value || column == Second ? QVariant(int(Qt::AlignRight | Qt::AlignVCenter)) : QVariant();
    case Qt::EditRole:
        if (column == Value) return row.value;
        [[fallthrough]];
    case Qt::DisplayRole:
        switch (column) {
        case Name: return row.pinned ? QStringLiteral("\u2605 ") + row.name : row.name;
        case Value: return displayValue(row);
        case Second: return m_rules->displayValue(*row.info, row.second);
        case Unit: return text(row.info->unit);
        case Limits: return m_rules->limitsText(row.name, *row.info, validationContext());
        case Condition: return conditionText(row.info->writable);
        case Description: return text(row.info->description);
        default: return {};
        }
    default: return {};
    }
}

QString VariableModel::displayValue(const Row& row) const {
    if (!row.readable) return tr("(not readable)");
    return m_rules->displayValue(*row.info, row.value);
}

bool VariableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (role != Qt::EditRole || index.column() != Value || !(flags(index) & Qt::ItemIsEditable)) return false;
    const QString name = data(index, NameRole).toString();
    const VariableRules::Verdict verdict = m_rules->check(name, value.toString(), validationContext());
    if (verdict.ok)
        emit editRequested(name, verdict.lines);
    else
        emit editRefused(name, verdict.message);
    return false; // the value shown changes when the drive is read back
}

Qt::ItemFlags VariableModel::flags(const QModelIndex& index) const {
    if (!index.isValid()) return Qt::NoItemFlags;
    Qt::ItemFlags f = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    if (index.internalId() == kGroupId || index.column() != Value) return f;
    const Row& row = m_rows[std::size_t(m_groups[std::size_t(index.internalId() - 1)].rows[std::size_t(index.row())])];
    const bool writable = m_rules->editable(row.name, *row.info);
    return writable ? f | Qt::ItemIsEditable : f;
}

QModelIndex VariableModel::indexOf(const QString& name, int column) const {
    const auto it = m_byName.constFind(name.toUpper());
    if (it == m_byName.constEnd()) return {};
    const int g = m_groupOfRow[std::size_t(*it)];
    return createIndex(m_positionInGroup[std::size_t(*it)], column, quintptr(g) + 1);
}

QStringList VariableModel::groupNames() const {
    QStringList names;
    for (const Group& g : m_groups) names << g.title;
    return names;
}

void VariableModel::rowChanged(int rowIndex) {
    const QModelIndex first = indexOf(m_rows[std::size_t(rowIndex)].name, 0);
    emit dataChanged(first, first.siblingAtColumn(ColumnCount - 1));
}

void VariableModel::setValue(const QString& name, const QString& printed) {
    const auto it = m_byName.constFind(name.toUpper());
    if (it == m_byName.constEnd()) return;
    Row& row = m_rows[std::size_t(*it)];
    const bool changed = !row.value.isEmpty() && row.value != printed;
    if (row.value == printed && row.changed == changed && row.readable) return;
    row.changed = changed || (row.changed && row.value == printed);
    row.value = printed;
    row.readable = true;
    rowChanged(*it);
    if (m_rules->scalesLimits(row.name)) { // the limits of other variables are in these units
        for (int g = 0; g < rowCount(); ++g) {
            const QModelIndex group = index(g, 0);
            emit dataChanged(index(0, Limits, group), index(rowCount(group) - 1, Limits, group));
        }
    }
}

const VariableModel::Row* VariableModel::find(const QString& name) const {
    const auto it = m_byName.constFind(name.toUpper());
    return it == m_byName.constEnd() ? nullptr : &m_rows[std::size_t(*it)];
}

template <class T>
void VariableModel::setField(const QString& name, T Row::*field, const T& to) {
    const auto it = m_byName.constFind(name.toUpper());
    if (it == m_byName.constEnd() || m_rows[std::size_t(*it)].*field == to) return;
    m_rows[std::size_t(*it)].*field = to;
    rowChanged(*it);
}

void VariableModel::setSecond(const QString& name, const QString& printed) {
    setField(name, &Row::second, printed);
}

QString VariableModel::second(const QString& name) const {
    const Row* row = find(name);
    return row ? row->second : QString();
}

QString VariableModel::value(const QString& name) const {
    const Row* row = find(name);
    return row ? row->value : QString();
}

std::optional<double> VariableModel::number(const QString& name) const {
    bool ok = false;
    const double v = value(name).toDouble(&ok);
    return ok ? std::optional<double>(v) : std::nullopt;
}

bool VariableModel::isChanged(const QString& name) const {
    const Row* row = find(name);
    return row && row->changed;
}

void VariableModel::clearChanged() {
    for (std::size_t i = 0; i < m_rows.size(); ++i) {
        if (!m_rows[i].changed) continue;
        m_rows[i].changed = false;
        rowChanged(int(i));
    }
}

void VariableModel::setUnreadable(const QString& name) {
    setField(name, &Row::readable, false);
}

bool VariableModel::isReadable(const QString& name) const {
    const Row* row = find(name);
    return row && row->readable;
}

void VariableModel::setPinned(const QString& name, bool pinned) {
    setField(name, &Row::pinned, pinned);
}

bool VariableModel::isPinned(const QString& name) const {
    const Row* row = find(name);
    return row && row->pinned;
}

QStringList VariableModel::pinned() const {
    QStringList names;
    for (const Row& row : m_rows)
        if (row.pinned) names << row.name;
    return names;
}

QList<QPair<QString, QString>> VariableModel::namedValues(const QStringList& names) const {
    QList<QPair<QString, QString>> out;
    for (const QString& name : names)
        if (const QString v = value(name); !v.isEmpty()) out.append({name, v});
    return out;
}

VariableRules::Context VariableModel::validationContext() const {
    return {[this](const QString& name) { return number(name); }};
}

} // namespace app
