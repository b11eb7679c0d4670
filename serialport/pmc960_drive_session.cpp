// Pmc960DriveSession: the contract's verbs in MPL.
#include "pmc960_drive_session.h"

#include "link.h"
#include "pmc960_download.h"
#include "pmc960_upload.h"

namespace serialport {

namespace {
constexpr int kRunTimeoutMs = 24 * 3600 * 1000; // a routine may run for as long as the machine does
constexpr char kEsc = 0x1B;
constexpr int kNotEnabled = 0xB6; // #B6: motion asked for while the servo is not enabled
} // namespace

Pmc960DriveSession::Pmc960DriveSession(Link& link, QObject* parent) : DriveSession(parent), m_session(link) {
    connect(&m_session, &Pmc960Session::stateChanged, this,
            [this](Pmc960Session::State s) { emit readyChanged(s == Pmc960Session::State::Ready); });
    connect(&m_session, &Pmc960Session::finished, this, [this](quint64 id, const Pmc960Response& r) {
        if (id == m_run) {
            m_run = 0;
            if (r.error) {
                QString text = QStringLiteral("#%1 %2").arg(QString::number(r.error, 16).toUpper(), r.errorText);
                if (r.error == kNotEnabled) text += QStringLiteral(" (SM2 enables the servo with both loops closed, seed-pmc960 §2)");
                return emit programEnded(true, text);
            }
            return emit programEnded(false, QStringLiteral("the routine ended"));
        }
        LineAnswer a;
        a.command = QString::fromLatin1(r.command).trimmed();
        for (const QString& line : r.value.split(QLatin1Char('\n'), Qt::SkipEmptyParts))
            if (!line.trimmed().isEmpty()) a.lines << line.trimmed();
        if (r.error) {
            a.errorCode = r.error;
            a.error = QStringLiteral("#%1 %2").arg(QString::number(r.error, 16).toUpper(), r.errorText);
        }
        emit answered(id, a);
    });
    connect(&m_session, &Pmc960Session::failed, this, [this](quint64 id, const QString& why) {
        if (id == m_run) {
            m_run = 0;
            return emit programEnded(!m_stopping, m_stopping ? QStringLiteral("stopped (ESC)") : why);
        }
        emit lost(id, why);
    });
    connect(&m_session, &Pmc960Session::rawReceived, this, &Pmc960DriveSession::onRunBytes);
    connect(&link, &Link::errorOccurred, this, &DriveSession::linkFailed);
}

// A display character (? ! &) ends an MPL command by itself; anything else ends with CR (L1169-1181).
quint64 Pmc960DriveSession::sendLine(const QString& line) {
    QByteArray bytes = line.trimmed().toLatin1();
    if (bytes.isEmpty() || !QByteArray("?!&").contains(bytes.back())) bytes += '\r';
    return m_session.send(bytes);
}

void Pmc960DriveSession::download(const QString& programText) {
    m_download = new Pmc960Download(m_session, programText, this);
    connect(m_download, &Pmc960Download::progress, this, &DriveSession::transferProgress);
    connect(m_download, &Pmc960Download::done, this, [this](const Pmc960DownloadResult& d) {
        m_download->deleteLater();
        TransferResult r;
        r.status = d.ok ? TransferResult::Status::Done
                   : d.cancelled ? TransferResult::Status::Cancelled
                                 : TransferResult::Status::Failed;
        if (d.ok) {
            r.verified = QStringLiteral("communications checksum %1").arg(d.driveChecksum, 4, 16, QLatin1Char('0'));
            r.message = QStringLiteral("Downloaded and verified (%1).").arg(r.verified);
            r.driveHolds = QStringLiteral("the new program");
        } else {
            r.message = d.error ? QStringLiteral("#%1 %2").arg(QString::number(d.error, 16).toUpper(), d.reason) : d.reason;
            // P{} erases the buffer before the lines go in (L1398-1439): whatever stopped the download
            // after that left part of the new program.
            r.driveHolds = QStringLiteral("part of the new program at most (the buffer is erased first); upload to see");
        }
        emit transferFinished(r);
    });
    m_download->start();
}

void Pmc960DriveSession::upload() {
    auto* up = new Pmc960Upload(m_session, this);
    connect(up, &Pmc960Upload::done, this, [this, up](bool ok, const QStringList& lines, const QString& reason) {
        up->deleteLater();
        TransferResult r;
        r.status = ok ? TransferResult::Status::Done : TransferResult::Status::Failed;
        r.lines = lines;
        r.message = ok ? QStringLiteral("Uploaded %1 line(s).").arg(lines.size()) : reason;
        r.driveHolds = QStringLiteral("its program, unchanged (an upload changes nothing)");
        emit transferFinished(r);
    });
    up->start();
}

void Pmc960DriveSession::cancelTransfer() {
    if (m_download) m_download->cancel();
}

// B<label> branches to the routine (L1135); the prompt comes back when it ends, so the request waits for
// as long as the routine runs. What the routine displays on the way is passed on as it arrives.
void Pmc960DriveSession::run(const QString& label) {
    m_stopping = false;
    m_runEcho = "B" + label.toLatin1();
    m_runSeen.clear();
    m_runStarted = false;
    m_run = m_session.send(m_runEcho + '\r', kRunTimeoutMs);
}

void Pmc960DriveSession::onRunBytes(const QByteArray& bytes) {
    if (!m_run) return;
    m_runSeen += bytes;
    if (!m_runSeen.startsWith(m_runEcho)) return;
    if (!m_runStarted) {
        m_runStarted = true;
        emit programStarted();
    }
    QByteArray body = m_runSeen.mid(m_runEcho.size());
    // Hold back what may be the start of the closing prompt (CR LF <id> }).
    const qsizetype cr = body.lastIndexOf('\r');
    const QByteArray shown = cr >= 0 ? body.left(cr) : body;
    if (shown.isEmpty()) return;
    m_runSeen = m_runEcho + body.mid(shown.size());
    QString text = QString::fromLatin1(shown).remove(QLatin1Char('\r'));
    if (text.startsWith(QLatin1Char('\n'))) text.remove(0, 1);
    if (!text.isEmpty()) emit programOutput(text + QLatin1Char('\n'));
}

void Pmc960DriveSession::stop() {
    m_stopping = true;
    m_session.resynchronise(QByteArray(1, kEsc));
}

} // namespace serialport
