// ErrorLogModel: family-neutral error rows shown with their family's words.
#include "error_log_model.h"

#include <QApplication>
#include <QBrush>
#include <QColor>
#include <QStyle>

namespace app {

namespace {
using Level = ErrorLogModel::Level;

QColor colourOf(Level level) {
    switch (level) {
    case Level::Info: return QColor(0x5f, 0x63, 0x68);
    case Level::Warning: return QColor(0xb0, 0x6c, 0x00);
    case Level::Error: return QColor(0xd9, 0x48, 0x00);
    case Level::Fault: return QColor(0xb3, 0x26, 0x1e);
    case Level::Firmware: return QColor(0x7b, 0x1f, 0xa2);
    }
    return {};
}

QStyle::StandardPixmap iconOf(Level level) {
    switch (level) {
    case Level::Info: return QStyle::SP_MessageBoxInformation;
    case Level::Warning: return QStyle::SP_MessageBoxWarning;
    default: return QStyle::SP_MessageBoxCritical;
    }
}

QString csvField(QString field) {
    if (field.contains(QLatin1Char(',')) || field.contains(QLatin1Char('"')) || field.contains(QLatin1Char('\n')))
        field = QLatin1Char('"') + field.replace(QLatin1Char('"'), QStringLiteral("\"\"")) + QLatin1Char('"');
    return field;
}
} // namespace

int ErrorLogModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : int(m_entries.size());
}

int ErrorLogModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant ErrorLogModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
    case Severity: return tr("Severity");
    case Code:
        // Each family's own name for the number: ERR n, the FAULTCODE display, #xx.
        switch (m_family) {
        case drive_core::DriveFamily::Bds5: return tr("ERR");
        case drive_core::DriveFamily::Sc750: return tr("Fault");
        default: return tr("Code");
        }
    case Message: return tr("Message");
    case Line: return tr("Line");
    case Source: return tr("When");
    case Hint: return tr("What to do");
    default: return {};
    }
}

QVariant ErrorLogModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= int(m_entries.size())) return {};
    const Entry& e = m_entries[std::size_t(index.row())];
    switch (role) {
    case ProgramLineRole: return e.programLine;
    case SeverityRole: return int(e.level);
    case Qt::DecorationRole:
        return index.column() == Severity ? QVariant(QApplication::style()->standardIcon(iconOf(e.level))) : QVariant();
    case Qt::ForegroundRole:
        return index.column() == Severity || index.column() == Message ? QVariant(QBrush(colourOf(e.level)))
                                                                       : QVariant();
    case Qt::ToolTipRole: return e.explanation.isEmpty() ? QVariant() : QVariant(e.explanation);
    case Qt::DisplayRole:
        switch (index.column()) {
        case Severity: return e.severity;
        case Code: return e.codeText;
        case Message: return e.detail.isEmpty() ? e.message : QStringLiteral("%1 '%2'").arg(e.message, e.detail);
        case Line: return e.programLine > 0 ? QVariant(e.programLine) : QVariant();
        case Source:
            if (e.origin == Origin::Reported) return e.seen.toString(QStringLiteral("HH:mm:ss"));
            return e.where.isEmpty() ? tr("history #%1").arg(e.historyPosition) : e.where;
        case Hint: return e.hint;
        default: return {};
        }
    default: return {};
    }
}

void ErrorLogModel::setHistory(std::vector<Entry> history) {
    beginResetModel();
    std::erase_if(m_entries, [](const Entry& e) { return e.origin == Origin::History; });
    int position = 0;
    for (Entry& e : history) {
        e.origin = Origin::History;
        e.historyPosition = ++position;
        m_entries.push_back(std::move(e));
    }
    endResetModel();
}

void ErrorLogModel::addReported(Entry entry, const QDateTime& when) {
    entry.origin = Origin::Reported;
    entry.seen = when;
    beginInsertRows({}, 0, 0);
    m_entries.insert(m_entries.begin(), std::move(entry));
    endInsertRows();
}

void ErrorLogModel::clear() {
    beginResetModel();
    m_entries.clear();
    endResetModel();
}

QString ErrorLogModel::toCsv() const {
    QString out = QStringLiteral("severity,code,message,line,entry,source,hint\n");
    for (int row = 0; row < rowCount(); ++row) {
        const Entry& e = m_entries[std::size_t(row)];
        QStringList fields{e.severity, e.codeText,
                           e.message,  e.programLine > 0 ? QString::number(e.programLine) : QString(),
                           e.detail,   data(index(row, Source)).toString(),
                           e.hint};
        for (QString& f : fields) f = csvField(f);
        out += fields.join(QLatin1Char(',')) + QLatin1Char('\n');
    }
    return out;
}

} // namespace app
