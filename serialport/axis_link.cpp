// AxisLink: select an axis, then carry its bytes.
#include "axis_link.h"

#include <QTimer>

namespace serialport {

using drive_core::DriveFamily;

namespace {
constexpr char kBds5Wake = '\\', kPmc960Attention = 0x1D;
constexpr int kSc750MaxAddress = 254;

bool bds5Id(const QString& id) {
    return id.size() == 1 && ((id[0] >= u'0' && id[0] <= u'9') || (id[0] >= u'A' && id[0] <= u'Z'));
}
} // namespace

QString axisIdProblem(DriveFamily family, const QString& id) {
    switch (family) {
    case DriveFamily::Bds5:
        return bds5Id(id) ? QString() : QStringLiteral("\"%1\" is not a BDS5 axis ID (one of 0-9 and A-Z)").arg(id);
    case DriveFamily::Sc750: {
        bool number = false;
        const int address = id.toInt(&number);
        return number && address >= 0 && address <= kSc750MaxAddress && !id.startsWith(u'+')
                   ? QString()
                   : QStringLiteral("\"%1\" is not an SC750 multidrop address (0-254, App. C)").arg(id);
    }
    case DriveFamily::Pmc960:
        return id.size() == 1 && id[0] >= u'!' && id[0] <= u'Z'
                   ? QString()
                   : QStringLiteral("\"%1\" is not a PMC-960 axis ID (one character 21H-5AH, as THI sets it)").arg(id);
    }
    return QStringLiteral("unknown family");
}

QByteArray axisSelectBytes(DriveFamily family, const QString& id) {
    if (!axisIdProblem(family, id).isEmpty()) return {};
    switch (family) {
    case DriveFamily::Bds5: return QByteArray(1, kBds5Wake) + id.toLatin1();
    case DriveFamily::Sc750: return "/" + QByteArray::number(id.toInt()).rightJustified(3, '0');
    case DriveFamily::Pmc960: return QByteArray(1, kPmc960Attention) + id.toLatin1();
    }
    return {};
}

QByteArray axisBroadcastBytes(DriveFamily family, const QString& line) {
    if (family != DriveFamily::Bds5 || line.isEmpty()) return {};
    return QByteArray(1, kBds5Wake) + '*' + line.toLatin1() + '\r' + axisReleaseBytes(family);
}

QByteArray axisReleaseBytes(DriveFamily family) {
    return family == DriveFamily::Bds5 ? QByteArray("\\\r") : QByteArray();
}

QStringList allAxisIds(DriveFamily family) {
    QStringList ids;
    switch (family) {
    case DriveFamily::Bds5:
        for (const QChar c : QStringLiteral("0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ")) ids << QString(c);
        break;
    case DriveFamily::Sc750:
        for (int a = 0; a <= kSc750MaxAddress; ++a) ids << QString::number(a);
        break;
    case DriveFamily::Pmc960:
        for (char c = 'A'; c <= 'Z'; ++c) ids << QString(QChar(c)); // the letters first: what THI is set to
        for (char c = '0'; c <= '9'; ++c) ids << QString(QChar(c));
        break;
    }
    return ids;
}

QStringList parseAxisIds(DriveFamily family, const QString& text, QString& error) {
    QStringList ids;
    const QStringList all = allAxisIds(family);
    const bool single = family != DriveFamily::Sc750;
    const QString upper = text.toUpper().remove(QLatin1Char(' '));
    QStringList parts;
    if (upper.contains(QLatin1Char(',')))
        parts = upper.split(QLatin1Char(','), Qt::SkipEmptyParts);
    else if (single && !upper.contains(QLatin1Char('-'))) // "ABD"
        for (const QChar c : upper) parts << QString(c);
    else if (!upper.isEmpty())
        parts << upper;
    for (const QString& part : parts) {
        const qsizetype dash = part.indexOf(QLatin1Char('-'), 1);
        const QString from = dash > 0 ? part.left(dash) : part, to = dash > 0 ? part.mid(dash + 1) : part;
        for (const QString& end : {from, to}) {
            if (const QString problem = axisIdProblem(family, end); !problem.isEmpty()) {
                error = problem;
                return {};
            }
        }
        const qsizetype a = all.indexOf(single ? from : QString::number(from.toInt()));
        const qsizetype b = all.indexOf(single ? to : QString::number(to.toInt()));
        if (a < 0 || b < a) {
            error = QStringLiteral("\"%1\" is not a range of axis IDs (first-last, in the order %2 ... %3)")
                        .arg(part, all.first(), all.last());
            return {};
        }
        for (qsizetype i = a; i <= b; ++i)
            if (!ids.contains(all[i])) ids << all[i];
    }
    if (ids.isEmpty()) error = QStringLiteral("no axis IDs given");
    return ids;
}

AxisLink::AxisLink(Link& line, DriveFamily family, QString id, QObject* parent)
    : Link(parent), m_line(&line), m_family(family), m_id(std::move(id)) {
    connect(&line, &Link::bytesReceived, this, [this](const QByteArray& bytes) {
        if (m_open) emit bytesReceived(bytes);
    });
    connect(&line, &Link::errorOccurred, this, [this](const QString& why) {
        if (m_open || m_opening) emit errorOccurred(why);
    });
    connect(&line, &Link::opened, this, [this] {
        if (m_opening) select();
    });
    connect(&line, &Link::closed, this, [this] {
        m_opening = false;
        if (!m_open) return;
        m_open = false;
        emit closed();
    });
}

AxisLink::AxisLink(std::shared_ptr<Link> line, DriveFamily family, QString id, QObject* parent)
    : AxisLink(*line, family, std::move(id), parent) {
    m_keep = std::move(line);
}

AxisLink::~AxisLink() {
    if (m_open && m_line && m_line->isOpen()) put(axisReleaseBytes(m_family));
}

void AxisLink::open() {
    if (m_open || m_opening) return;
    const QString problem = axisIdProblem(m_family, m_id);
    if (!problem.isEmpty()) {
        QTimer::singleShot(0, this, [this, problem] { emit errorOccurred(problem); });
        return;
    }
    m_opening = true;
    if (m_line->isOpen())
        QTimer::singleShot(0, this, [this] {
            if (m_opening) select();
        });
    else
        m_line->open();
}

void AxisLink::select() {
    m_opening = false;
    put(axisSelectBytes(m_family, m_id));
    m_open = true;
    emit opened();
}

void AxisLink::close() {
    m_opening = false;
    if (!m_open) return;
    m_open = false;
    if (m_line && m_line->isOpen()) {
        const QByteArray release = axisReleaseBytes(m_family);
        if (!release.isEmpty()) put(release);
    }
    emit closed();
}

void AxisLink::write(const QByteArray& bytes) {
    if (!m_open) {
        emit errorOccurred(tr("axis %1 is not selected: nothing was sent").arg(m_id));
        return;
    }
    put(bytes);
}

void AxisLink::put(const QByteArray& bytes) {
    if (bytes.isEmpty()) return;
    m_written += bytes.size();
    m_line->write(bytes);
}

QString AxisLink::description() const {
    return tr("axis %1 on %2").arg(m_id, m_line ? m_line->description() : tr("a closed line"));
}

} // namespace serialport
