// ErrorLogModel: error rows with the catalog's words.
#include "error_log_model.h"

#include <QApplication>
#include <QBrush>
#include <QColor>
#include <QStyle>

namespace app {

namespace cat = drive_core::catalog::bds5;

namespace {
QString text(std::string_view view) {
    return QString::fromLatin1(view.data(), qsizetype(view.size()));
}

cat::Severity severityOf(int code) {
    const cat::ErrorInfo* info = cat::findError(code);
    return info ? info->severity : cat::Severity::Break;
}

QColor colourOf(cat::Severity severity) {
    switch (severity) {
    case cat::Severity::HistoryOnly: return QColor(0x5f, 0x63, 0x68);
    case cat::Severity::Warning: return QColor(0xb0, 0x6c, 0x00);
    case cat::Severity::Break: return QColor(0xd9, 0x48, 0x00);
    case cat::Severity::Disable: return QColor(0xb3, 0x26, 0x1e);
    case cat::Severity::Firmware: return QColor(0x7b, 0x1f, 0xa2);
    }
    return {};
}

QStyle::StandardPixmap iconOf(cat::Severity severity) {
    switch (severity) {
    case cat::Severity::HistoryOnly: return QStyle::SP_MessageBoxInformation;
    case cat::Severity::Warning: return QStyle::SP_MessageBoxWarning;
    default: return QStyle::SP_MessageBoxCritical;
    }
}

QString csvField(QString field) {
    if (field.contains(QLatin1Char(',')) || field.contains(QLatin1Char('"')) || field.contains(QLatin1Char('\n')))
        field = QLatin1Char('"') + field.replace(QLatin1Char('"'), QStringLiteral("\"\"")) + QLatin1Char('"');
    return field;
}
} // namespace

QString ErrorLogModel::severityName(cat::Severity severity) {
    switch (severity) {
    case cat::Severity::HistoryOnly: return tr("Logged");
    case cat::Severity::Warning: return tr("Warning");
    case cat::Severity::Break: return tr("Break");
    case cat::Severity::Disable: return tr("Disable");
    case cat::Severity::Firmware: return tr("Firmware");
    }
    return {};
}

QString ErrorLogModel::fixHint(int code) {
    const cat::ErrorInfo* info = cat::findError(code);
    if (!info) return tr("Not in the BDS5's error table.");
    return info->remedy.empty() ? text(info->meaning) : text(info->remedy);
}

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
    case Code: return tr("ERR");
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
    const cat::Severity severity = severityOf(e.error.code);
    switch (role) {
    case ProgramLineRole: return e.error.programLine;
    case SeverityRole: return int(severity);
    case Qt::DecorationRole:
        return index.column() == Severity ? QVariant(QApplication::style()->standardIcon(iconOf(severity)))
                                          : QVariant();
    case Qt::ForegroundRole:
        return index.column() == Severity || index.column() == Message ? QVariant(QBrush(colourOf(severity)))
                                                                       : QVariant();
    case Qt::ToolTipRole: {
        const cat::ErrorInfo* info = cat::findError(e.error.code);
        return info ? QStringLiteral("%1\n\n%2 (%3)")
                          .arg(text(info->meaning), fixHint(e.error.code), text(info->manualLines))
                    : QVariant();
    }
    case Qt::DisplayRole:
        switch (index.column()) {
        case Severity: return severityName(severity);
        case Code: return e.error.code;
        case Message:
            return e.error.entry.isEmpty() ? e.error.message
                                           : QStringLiteral("%1 '%2'").arg(e.error.message, e.error.entry);
        case Line: return e.error.programLine > 0 ? QVariant(e.error.programLine) : QVariant();
        case Source:
            return e.origin == Origin::History ? tr("history #%1").arg(e.historyPosition)
                                               : e.seen.toString(QStringLiteral("HH:mm:ss"));
        case Hint: return fixHint(e.error.code);
        default: return {};
        }
    default: return {};
    }
}

void ErrorLogModel::setHistory(const QList<serialport::Bds5ErrorLine>& history) {
    beginResetModel();
    std::erase_if(m_entries, [](const Entry& e) { return e.origin == Origin::History; });
    int position = 0;
    for (const serialport::Bds5ErrorLine& error : history)
        m_entries.push_back({error, Origin::History, ++position, {}});
    endResetModel();
}

void ErrorLogModel::addReported(const serialport::Bds5ErrorLine& error, const QDateTime& when) {
    beginInsertRows({}, 0, 0);
    m_entries.insert(m_entries.begin(), Entry{error, Origin::Reported, 0, when});
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
        QStringList fields{data(index(row, Severity)).toString(),
                           QString::number(e.error.code),
                           e.error.message,
                           e.error.programLine > 0 ? QString::number(e.error.programLine) : QString(),
                           e.error.entry,
                           data(index(row, Source)).toString(),
                           fixHint(e.error.code)};
        for (QString& f : fields) f = csvField(f);
        out += fields.join(QLatin1Char(',')) + QLatin1Char('\n');
    }
    return out;
}

} // namespace app
