// The SC750 session: frame queue, reply matching, time-outs, events (see sc750_session.h).
#include "sc750_session.h"

#include "drive_core/sc750/sc750_frame.h"

namespace serialport {

namespace sc = drive_core::sc750;

namespace {
constexpr int kTurnaroundMs = 400; // the drive's answer time on top of the wire time (chosen)
constexpr int kMaxFrame = 400;
} // namespace

Sc750Session::Sc750Session(Link& link, QObject* parent) : QObject(parent), m_link(link) {
    qRegisterMetaType<Sc750Reply>();
    connect(&m_timeout, &DriveTimeout::timeout, this, &Sc750Session::onTimeout);
    connect(&m_link, &Link::bytesReceived, this, &Sc750Session::onBytes);
    connect(&m_link, &Link::opened, this, &Sc750Session::pump);
}

quint64 Sc750Session::send(char letter, const QString& payload, bool repeatable) {
    const quint64 id = m_nextId++;
    const std::string frame = sc::encodeFrame(letter, payload.toStdString());
    m_queue.push_back(Pending{id, letter, QByteArray::fromStdString(frame), 1, repeatable});
    pump();
    return id;
}

void Sc750Session::sendStop() {
    write(QByteArray(1, sc::kStopByte));
    emit stopSent();
}

void Sc750Session::sendProgramInput(const QByteArray& bytes) {
    QByteArray clean = bytes;
    clean.replace(char(sc::kSoh), QByteArray()); // SOH would open a protocol frame
    write(clean);
}

void Sc750Session::logOn(int axis) {
    if (axis >= 0 && axis < 255) write("/" + QByteArray::number(axis).rightJustified(3, '0'));
}

void Sc750Session::cancelPending() {
    std::deque<Pending> dropped;
    dropped.swap(m_queue);
    for (const Pending& p : dropped) emit failed(p.id, QStringLiteral("cancelled"));
}

void Sc750Session::pump() {
    if (m_current || m_queue.empty() || !m_link.isOpen()) return;
    m_current = m_queue.front();
    m_queue.pop_front();
    m_timeout.start(timeoutMs(m_current->frame));
    write(m_current->frame);
}

int Sc750Session::timeoutMs(const QByteArray& frame) const {
    const int baud = m_link.baudRate();
    if (baud <= 0) return kTurnaroundMs;
    // the command and a reply of up to the longest frame, ten bits a character
    return int((frame.size() + kMaxFrame) * 10LL * 1000 / baud) + kTurnaroundMs;
}

void Sc750Session::write(const QByteArray& bytes) {
    if (!m_link.isOpen()) return;
    m_link.write(bytes);
    emit rawSent(bytes);
}

void Sc750Session::onBytes(const QByteArray& bytes) {
    emit rawReceived(bytes);
    for (const char c : bytes) {
        if (c == sc::kSoh) {
            m_inFrame = true;
            m_frame.clear();
        } else if (m_inFrame && c == sc::kFrameEnd) {
            m_inFrame = false;
            if (!m_output.isEmpty()) emit programOutput(std::exchange(m_output, {}));
            onFrame(m_frame);
        } else if (m_inFrame) {
            if (m_frame.size() < kMaxFrame) m_frame += c;
        } else {
            m_output += c;
        }
    }
    if (!m_output.isEmpty()) emit programOutput(std::exchange(m_output, {}));
}

void Sc750Session::onFrame(const QByteArray& body) {
    const auto frame = sc::decodeFrame(body.toStdString());
    if (!frame) { // damaged: the time-out retries the command, or a repeatable one goes again now
        if (m_current && m_current->repeatable) {
            if (m_current->retries-- > 0) {
                m_timeout.start(timeoutMs(m_current->frame));
                write(m_current->frame);
                return;
            }
            m_timeout.stop();
            const Pending lost = *m_current;
            m_current.reset();
            emit failed(lost.id, QStringLiteral("no answer from the SC750 (its answer was damaged)"));
            pump();
        }
        return;
    }
    const QString payload = QString::fromStdString(frame->payload);
    switch (frame->letter) {
    case 'b': emit breakpointHit(payload.toInt()); return;
    case 'e': emit programEnded(payload.toInt()); return;
    case 'h': emit programStopped(payload.toInt()); return;
    case 'f': {
        const QStringList parts = payload.split(QLatin1Char(','));
        emit runTimeError(parts.value(0).toInt(), parts.value(1).toInt(), parts.mid(2).join(QLatin1Char(',')));
        return;
    }
    default: break;
    }
    const char expected = m_current && m_current->letter == '?' ? 'S' : m_current ? m_current->letter : 0;
    if (!m_current || (frame->letter != expected && frame->letter != '!')) {
        if (frame->letter == 'H') emit programStopped(payload.toInt()); // the answer to Ctrl C
        return;
    }
    // The drive saw our frame damaged ("!01 BAD FRAME", "!01 FRAME TOO LONG" when its CR was lost): it did
    // nothing, so the command goes again at once, as after a time-out.
    if (frame->letter == '!' && payload.startsWith(QLatin1String("01 ")) && m_current->retries-- > 0) {
        m_timeout.start(timeoutMs(m_current->frame));
        write(m_current->frame);
        return;
    }
    m_timeout.stop();
    const Pending done = *m_current;
    m_current.reset();
    if (frame->letter == '!')
        emit failed(done.id, payload);
    else
        emit finished(done.id, Sc750Reply{frame->letter, payload});
    pump();
}

void Sc750Session::onTimeout() {
    if (!m_current) return;
    if (m_current->retries-- > 0) {
        m_timeout.start(timeoutMs(m_current->frame));
        write(m_current->frame);
        return;
    }
    const Pending lost = *m_current;
    m_current.reset();
    emit failed(lost.id, QStringLiteral("no answer from the SC750 (time-out)"));
    pump();
}

} // namespace serialport
