// Sc750DriveSession: the contract's verbs in Motion Dialogue frames.
#include "sc750_drive_session.h"

#include "link.h"
#include "sc750_download.h"

#include "drive_core/sc750/sc750_bin.h"
#include "drive_core/sc750/sc750_compiler.h"

#include <QRegularExpression>

#include <span>

namespace serialport {

namespace {
constexpr int kSourceChunk = 64; // PROTOCOL.md §4: 64 bytes a t frame

// The real-time functions an F frame calls (L2796-2812).
bool isFunction(const QString& word) {
    static const QStringList functions{QStringLiteral("GO.VEL"),       QStringLiteral("GO.INCR"),
                                       QStringLiteral("GO.ABS"),       QStringLiteral("GO.HOME"),
                                       QStringLiteral("ABORT.MOTION"), QStringLiteral("UPD.MOVE"),
                                       QStringLiteral("PAUSE")};
    return functions.contains(word);
}

LineAnswer errorAnswer(const QString& command, const Sc750Reply& reply) {
    LineAnswer a;
    a.command = command;
    a.errorCode = reply.errorCode();
    a.error = QStringLiteral("!") + reply.payload;
    return a;
}
} // namespace

Sc750DriveSession::Sc750DriveSession(Link& link, QObject* parent) : DriveSession(parent), m_session(link) {
    connect(&m_session, &Sc750Session::finished, this, [this](quint64 id, const Sc750Reply& reply) {
        if (const auto line = m_lines.find(id); line != m_lines.end()) {
            const QString command = line->second;
            m_lines.erase(line);
            if (reply.isError()) return emit answered(id, errorAnswer(command, reply));
            LineAnswer a;
            a.command = command;
            // G answers NAME=value, P the value now held, F the function's name: the value is what a user asked.
            a.lines << (reply.letter == 'G' || reply.letter == 'P' ? reply.payload.section(QLatin1Char('='), 1)
                                                                   : reply.payload);
            return emit answered(id, a);
        }
        const auto it = m_requests.find(id);
        if (it == m_requests.end()) return;
        auto [onReply, onFail] = it->second;
        m_requests.erase(it);
        if (reply.isError()) return onFail(QStringLiteral("!") + reply.payload);
        onReply(reply);
    });
    connect(&m_session, &Sc750Session::failed, this, [this](quint64 id, const QString& why) {
        if (const auto line = m_lines.find(id); line != m_lines.end()) {
            const QString command = line->second;
            m_lines.erase(line);
            // The drive's refusal arrives as its "nn TEXT" (PROTOCOL.md §3); anything else is the session's
            // own reason (a time-out, the link closed).
            static const QRegularExpression driveError(QStringLiteral("^\\d\\d "));
            if (driveError.match(why).hasMatch()) return emit answered(id, errorAnswer(command, Sc750Reply{'!', why}));
            return emit lost(id, why);
        }
        const auto it = m_requests.find(id);
        if (it == m_requests.end()) return;
        const OnFail onFail = it->second.second;
        m_requests.erase(it);
        onFail(why);
    });
    connect(&m_session, &Sc750Session::programOutput, this,
            [this](const QByteArray& bytes) { emit programOutput(QString::fromLatin1(bytes).remove(QLatin1Char('\r'))); });
    connect(&m_session, &Sc750Session::programEnded, this, [this](int line) {
        m_running = false;
        emit programEnded(false, QStringLiteral("the program ended at line %1").arg(line));
    });
    connect(&m_session, &Sc750Session::programStopped, this, [this](int line) {
        m_running = false;
        emit programEnded(false, QStringLiteral("the program stopped at line %1").arg(line));
    });
    connect(&m_session, &Sc750Session::breakpointHit, this, [this](int line) {
        emit programEnded(false, QStringLiteral("the program stopped at its breakpoint on line %1").arg(line));
    });
    connect(&m_session, &Sc750Session::runTimeError, this, [this](int code, int line, const QString& text) {
        m_running = false;
        emit programEnded(true, QStringLiteral("F%1 at line %2: %3").arg(code).arg(line).arg(text));
    });
    // Ready once the drive has identified itself (V): the SC750 sends nothing of its own at power-up.
    const auto identify = [this] {
        m_identified = false;
        request('V', {}, [this](const Sc750Reply&) {
            m_identified = true;
            emit readyChanged(true);
        }, [this](const QString& why) { emit linkFailed(QStringLiteral("the SC750 does not answer: %1").arg(why)); });
    };
    connect(&link, &Link::opened, this, identify);
    connect(&link, &Link::errorOccurred, this, &DriveSession::linkFailed);
    if (link.isOpen()) identify();
}

void Sc750DriveSession::request(char letter, const QString& payload, OnReply onReply, OnFail onFail) {
    const bool repeatable = letter == 'V' || letter == 'u' || letter == 't' || letter == 'T' || letter == 'Q';
    m_requests[m_session.send(letter, payload, repeatable)] = {std::move(onReply), std::move(onFail)};
}

quint64 Sc750DriveSession::sendLine(const QString& line) {
    const QString text = line.trimmed().toUpper();
    quint64 id = 0;
    if (text.contains(QLatin1Char('=')))
        id = m_session.send('P', text.section(QLatin1Char('='), 0, 0).trimmed() + QLatin1Char('=') +
                                     text.section(QLatin1Char('='), 1).trimmed());
    else if (isFunction(text))
        id = m_session.send('F', text);
    else
        id = m_session.send('G', text, true);
    m_lines[id] = line;
    return id;
}

void Sc750DriveSession::finishTransfer(TransferResult result) {
    m_transferring = false;
    m_download = nullptr;
    emit transferFinished(result);
}

void Sc750DriveSession::download(const QString& programText) {
    m_transferring = true;
    m_cancelled = false;
    m_source = programText.toLatin1();
    const auto compiled = drive_core::sc750::compile(m_source.toStdString());
    if (!compiled.ok()) {
        TransferResult r;
        r.message = QStringLiteral("Compile error, line %1 col %2: %3")
                        .arg(compiled.error->line)
                        .arg(compiled.error->column)
                        .arg(QString::fromStdString(compiled.error->message));
        r.driveHolds = QStringLiteral("its old program, unchanged (nothing was sent)");
        r.errors.push_back({compiled.error->line, 0, QString::fromStdString(compiled.error->text())});
        return finishTransfer(r);
    }
    const std::uint32_t crc = drive_core::sc750::crc32(std::span(compiled.bin));
    m_verified = QStringLiteral("CRC-32 %1 of the %2-byte .BIN, checked by the drive")
                     .arg(QString::number(crc, 16).rightJustified(8, QLatin1Char('0')).toUpper())
                     .arg(compiled.bin.size());
    m_download = new Sc750Download(m_session, compiled.bin, this);
    connect(m_download, &Sc750Download::progress, this, &DriveSession::transferProgress);
    connect(m_download, &Sc750Download::finished, this, [this](bool ok, const QString& message) {
        m_download->deleteLater();
        m_download = nullptr;
        if (!ok) {
            TransferResult r;
            r.status = m_cancelled ? TransferResult::Status::Cancelled : TransferResult::Status::Failed;
            r.message = message;
            // The drive replaces its program only after Z's CRC and version check (PROTOCOL.md §4).
            r.driveHolds = QStringLiteral("its old program (the drive checks the CRC before replacing it)");
            return finishTransfer(r);
        }
        const std::uint32_t sourceCrc = drive_core::sc750::crc32(
            std::span(reinterpret_cast<const std::uint8_t*>(m_source.constData()), std::size_t(m_source.size())));
        const QString payload =
            QStringLiteral("%1,%2").arg(m_source.size()).arg(sourceCrc, 8, 16, QLatin1Char('0')).toUpper();
        request('T', payload, [this](const Sc750Reply&) { storeSource(0); }, [this](const QString& why) {
            TransferResult r;
            r.message = QStringLiteral("The program is loaded, but its source was not stored: %1").arg(why);
            r.driveHolds = QStringLiteral("the new program, without its source");
            finishTransfer(r);
        });
    });
    m_download->start();
}

// The source into non-volatile memory, 64 bytes a t frame, then Q (L462-468).
void Sc750DriveSession::storeSource(int offset) {
    const auto failed = [this](const QString& why) {
        TransferResult r;
        r.message = QStringLiteral("The program is loaded, but its source was not stored: %1").arg(why);
        r.driveHolds = QStringLiteral("the new program, without its source");
        finishTransfer(r);
    };
    if (offset >= m_source.size()) {
        return request('Q', {}, [this](const Sc750Reply&) {
            TransferResult r;
            r.status = TransferResult::Status::Done;
            r.verified = m_verified;
            r.message = QStringLiteral("Downloaded and verified (%1); source stored.").arg(m_verified);
            r.driveHolds = QStringLiteral("the new program and its source");
            finishTransfer(r);
        }, failed);
    }
    const QByteArray chunk = m_source.mid(offset, kSourceChunk);
    request('t', QStringLiteral("%1,%2").arg(offset).arg(QString::fromLatin1(chunk.toHex().toUpper())),
            [this](const Sc750Reply& reply) { storeSource(int(reply.payload.toLongLong())); }, failed);
}

void Sc750DriveSession::upload() {
    m_transferring = true;
    m_cancelled = false;
    m_source.clear();
    askSource();
}

void Sc750DriveSession::askSource() {
    if (m_cancelled) {
        TransferResult r;
        r.status = TransferResult::Status::Cancelled;
        r.message = QStringLiteral("Upload cancelled.");
        r.driveHolds = QStringLiteral("its program, unchanged (an upload changes nothing)");
        return finishTransfer(r);
    }
    request('u', QString::number(m_source.size()), [this](const Sc750Reply& reply) {
        const QByteArray chunk = QByteArray::fromHex(reply.payload.section(QLatin1Char(','), 1).toLatin1());
        if (!chunk.isEmpty()) {
            m_source += chunk;
            emit transferProgress(m_source.size(), 0);
            return askSource();
        }
        TransferResult r;
        r.driveHolds = QStringLiteral("its program, unchanged (an upload changes nothing)");
        r.status = TransferResult::Status::Done;
        if (m_source.isEmpty()) { // as a BDS5 without a program uploads no lines: a state, not a failure
            r.message = QStringLiteral("The controller holds no stored source: no lines.");
            return finishTransfer(r);
        }
        QString text = QString::fromLatin1(m_source).remove(QLatin1Char('\r'));
        if (text.endsWith(QLatin1Char('\n'))) text.chop(1);
        r.lines = text.split(QLatin1Char('\n'));
        r.message = QStringLiteral("Uploaded the stored source: %1 bytes.").arg(m_source.size());
        finishTransfer(r);
    }, [this](const QString& why) {
        TransferResult r;
        r.message = QStringLiteral("Upload failed: %1").arg(why);
        r.driveHolds = QStringLiteral("its program, unchanged (an upload changes nothing)");
        finishTransfer(r);
    });
}

void Sc750DriveSession::cancelTransfer() {
    m_cancelled = true;
    if (m_download) m_download->cancel();
}

void Sc750DriveSession::run(const QString& label) {
    if (!label.isEmpty())
        return emit programEnded(true, QStringLiteral("the SC750 runs its program from the top (R); it cannot "
                                                      "start at a label (\"%1\")").arg(label));
    m_running = true;
    request('R', {}, [this](const Sc750Reply&) { emit programStarted(); }, [this](const QString& why) {
        m_running = false;
        emit programEnded(true, QStringLiteral("the drive refused R: %1").arg(why));
    });
}

void Sc750DriveSession::stop() {
    m_session.sendStop();
}

} // namespace serialport
