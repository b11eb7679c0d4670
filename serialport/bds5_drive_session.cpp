// Bds5DriveSession: the contract's verbs in BDS5 terms.
#include "bds5_drive_session.h"

#include "bds5_download.h"
#include "bds5_upload.h"

namespace serialport {

Bds5DriveSession::Bds5DriveSession(Link& link, QObject* parent) : DriveSession(parent), m_session(link) {
    connect(&m_session, &Bds5Session::stateChanged, this,
            [this](Bds5Session::State s) { emit readyChanged(s == Bds5Session::State::Ready); });
    connect(&m_session, &Bds5Session::finished, this, [this](quint64 id, const Bds5Response& r) {
        LineAnswer a;
        a.command = r.command;
        a.lines = r.lines;
        a.garbled = r.garbled;
        if (!r.errors.isEmpty()) {
            const Bds5ErrorLine& e = r.errors.first();
            a.errorCode = e.code;
            a.error = QStringLiteral("ERR %1 %2").arg(e.code).arg(e.message);
            for (const Bds5ErrorLine& more : r.errors)
                a.lines << QStringLiteral("ERR %1 '%2' %3").arg(more.code).arg(more.entry, more.message);
        }
        emit answered(id, a);
    });
    connect(&m_session, &Bds5Session::failed, this, &DriveSession::lost);
    connect(&m_session, &Bds5Session::rawReceived, this, &Bds5DriveSession::onRunBytes);
    connect(&link, &Link::errorOccurred, this, &DriveSession::linkFailed);
}

quint64 Bds5DriveSession::sendLine(const QString& line) {
    return m_session.send(line);
}

quint64 Bds5DriveSession::sendQuiet(const QString& line) {
    return m_session.send(line, Bds5Session::Echo::Quiet);
}

TransferResult Bds5DriveSession::toResult(const Bds5TransferResult& r, int linesSent) {
    using S = Bds5TransferResult::Status;
    TransferResult t;
    t.status = r.status == S::Ok ? TransferResult::Status::Done
               : r.status == S::Cancelled ? TransferResult::Status::Cancelled
                                          : TransferResult::Status::Failed;
    t.message = r.summary;
    t.lines = r.lines;
    if (r.checksum) t.verified = QStringLiteral("read back, P CHECKSUM %1").arg(*r.checksum);
    for (const Bds5LineError& e : r.errors)
        t.errors.push_back({e.sourceLine, e.error.code,
                            QStringLiteral("ERR %1 '%2' %3").arg(e.error.code).arg(e.error.entry, e.error.message)});
    // What the drive holds: a refusal changed nothing; >BDS replaces the program line by line, so a download
    // stopped part-way leaves the lines the drive acknowledged (L1615-1640).
    if (linesSent < 0) {
        t.driveHolds = QStringLiteral("its program, unchanged (an upload changes nothing)");
    } else if (r.status == S::Ok) {
        t.driveHolds = QStringLiteral("the new program");
    } else if (r.status == S::Refused || r.linesDone == 0) {
        t.driveHolds = QStringLiteral("its old program, unchanged");
    } else if (r.status == S::Mismatch) {
        t.driveHolds = QStringLiteral("a program that differs from the file at line %1").arg(r.mismatchSourceLine);
    } else {
        t.driveHolds = QStringLiteral("the first %1 of %2 lines").arg(r.linesDone).arg(linesSent);
    }
    return t;
}

void Bds5DriveSession::watch(Bds5Transfer* transfer, int linesSent) {
    m_transfer = transfer;
    connect(transfer, &Bds5Transfer::progress, this,
            [this](int done, int total) { emit transferProgress(done, total); });
    connect(transfer, &Bds5Transfer::finished, this, [this, transfer, linesSent](const Bds5TransferResult& r) {
        transfer->deleteLater();
        emit transferFinished(toResult(r, linesSent));
    });
    transfer->start();
}

void Bds5DriveSession::download(const QString& programText) {
    auto* d = new Bds5Download(m_session, programText, {}, this);
    watch(d, int(programText.split(QLatin1Char('\n'), Qt::SkipEmptyParts).size()));
}

void Bds5DriveSession::upload() {
    watch(new Bds5Upload(m_session, this), -1);
}

void Bds5DriveSession::cancelTransfer() {
    if (m_transfer) m_transfer->cancel();
}

// RUN gives no prompt while the program runs (L1254): what follows the echo is the program's output until
// the --> prompt comes back (it ended) or an ERR line (it stopped on an error).
void Bds5DriveSession::run(const QString& label) {
    m_runEcho = (label.isEmpty() ? QByteArray("RUN") : "RUN " + label.toLatin1()) + "\r\n";
    m_runBytes.clear();
    m_runError.clear();
    m_runStarted = false;
    m_running = true;
    m_session.sendRaw(m_runEcho.left(m_runEcho.size() - 1)); // RUN <label> CR
}

void Bds5DriveSession::onRunBytes(const QByteArray& bytes) {
    if (!m_running) return;
    m_runBytes += bytes;
    if (!m_runBytes.startsWith(m_runEcho)) {
        if (m_runEcho.startsWith(m_runBytes)) return; // the echo is still arriving
        // Refused at once: an error where the echo should end, then the prompt.
        if (!m_runBytes.endsWith("-->")) return;
        m_running = false;
        const QString text = QString::fromLatin1(m_runBytes).remove(QLatin1Char('\r'));
        const qsizetype err = text.indexOf(QStringLiteral("ERR"));
        emit programEnded(true, err >= 0 ? text.mid(err).section(QLatin1Char('\n'), 0, 0).trimmed()
                                         : QStringLiteral("the drive refused RUN"));
        return;
    }
    if (!m_runStarted) {
        m_runStarted = true;
        emit programStarted();
    }
    QByteArray body = m_runBytes.mid(m_runEcho.size());
    const qsizetype lineEnd = body.lastIndexOf('\n');
    const bool ended = body.endsWith("\r\n-->") || body == "-->";
    QByteArray complete = ended ? body.left(body.size() - 3) : body.left(lineEnd + 1);
    m_runBytes = m_runEcho + body.mid(complete.size());
    if (!complete.isEmpty()) {
        const QString text = QString::fromLatin1(complete).remove(QLatin1Char('\r'));
        emit programOutput(text);
        for (const QString& line : text.split(QLatin1Char('\n')))
            if (parseErrorLine(line)) m_runError = line.trimmed();
    }
    if (ended) {
        m_running = false;
        if (!m_runError.isEmpty()) return emit programEnded(true, m_runError);
        emit programEnded(false, QStringLiteral("the program ended"));
    }
}

void Bds5DriveSession::stop() {
    m_session.sendUrgent("\x18");
}

} // namespace serialport
