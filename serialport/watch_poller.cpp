// WatchPoller: one sample of a few values, in the family's way of reading them.
#include "watch_poller.h"

#include "pmc960_drive_session.h"

#include <optional>

namespace serialport {

namespace {
// A value as a drive prints it: a number, or a BDS5 switch's ON/OFF as 1/0.
std::optional<double> number(const QString& word) {
    if (word.compare(QLatin1String("ON"), Qt::CaseInsensitive) == 0) return 1;
    if (word.compare(QLatin1String("OFF"), Qt::CaseInsensitive) == 0) return 0;
    bool ok = false;
    const double v = word.trimmed().toDouble(&ok);
    return ok ? std::optional<double>(v) : std::nullopt;
}

// The PMC-960's status poll letter for a watch name (watch_choices.cpp): G! g, SF! f, V! v, I! i.
char pollLetter(const QString& name) {
    const QString upper = name.toUpper();
    return upper == QLatin1String("SF") ? 'f' : char(upper.at(0).toLower().toLatin1());
}
} // namespace

WatchPoller::WatchPoller(DriveSession& session, QObject* parent) : QObject(parent), m_session(session) {
    connect(&session, &DriveSession::answered, this, &WatchPoller::onAnswered);
    connect(&session, &DriveSession::lost, this, &WatchPoller::onLost);
    if (auto* pmc960 = dynamic_cast<Pmc960DriveSession*>(&session))
        connect(&pmc960->pmc960(), &Pmc960Session::pollAnswered, this, &WatchPoller::onStatusPolled);
}

void WatchPoller::poll(const QStringList& names) {
    m_names = names;
    m_values.clear();
    if (m_session.family() == drive_core::DriveFamily::Bds5) {
        m_pending = m_session.sendQuiet(QStringLiteral("P ") + names.join(QLatin1Char(' ')));
        return;
    }
    pollNext();
}

void WatchPoller::cancel() {
    m_pending = 0;
}

int WatchPoller::minimumIntervalMs(drive_core::DriveFamily family) {
    // The PMC-960's status panel polls only while the line is idle: leave it idle half the time.
    return family == drive_core::DriveFamily::Pmc960 ? 25 : 0;
}

void WatchPoller::pollNext() {
    const QString& name = m_names.at(m_values.size());
    if (auto* pmc960 = dynamic_cast<Pmc960DriveSession*>(&m_session))
        m_pending = pmc960->pmc960().poll(pollLetter(name));
    else
        m_pending = m_session.sendQuiet(name); // SC750: a G frame
}

void WatchPoller::onAnswered(quint64 id, const LineAnswer& answer) {
    if (!m_pending || id != m_pending) return;
    m_pending = 0;
    if (!answer.ok()) return emit failed(tr("the drive answered %1 to \"%2\"").arg(answer.error, answer.command), true);
    if (m_session.family() == drive_core::DriveFamily::Bds5) {
        // P prints the values on one line, blank-separated.
        const QStringList words = answer.lines.join(QLatin1Char(' ')).split(QLatin1Char(' '), Qt::SkipEmptyParts);
        QList<double> values;
        for (int i = 0; i < m_names.size() && words.size() >= m_names.size() && !answer.garbled; ++i) {
            const std::optional<double> v = number(words[i]);
            if (!v) return emit answered({}); // a damaged line: no sample this time
            values.append(*v);
        }
        return emit answered(values);
    }
    take(answer.lines.value(0));
}

void WatchPoller::onStatusPolled(quint64 id, char, const QString& value) {
    if (!m_pending || id != m_pending) return;
    m_pending = 0;
    take(value);
}

void WatchPoller::take(const QString& word) {
    const QString& name = m_names.at(m_values.size());
    const std::optional<double> v = number(word);
    if (!v) {
        const bool pmc960 = m_session.family() == drive_core::DriveFamily::Pmc960;
        return emit failed(pmc960 ? tr("%1 answered \"%2\", not a decimal number (set the controller's output "
                                       "format to decimal)")
                                        .arg(name, word.trimmed())
                                  : tr("%1 is not a number (\"%2\")").arg(name, word.trimmed()),
                           true);
    }
    m_values.append(*v);
    if (m_values.size() < m_names.size()) return pollNext();
    emit answered(m_values);
}

void WatchPoller::onLost(quint64 id, const QString& reason) {
    if (!m_pending || id != m_pending) return;
    m_pending = 0;
    emit failed(reason, false);
}

} // namespace serialport
