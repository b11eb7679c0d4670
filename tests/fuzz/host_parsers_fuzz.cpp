// libFuzzer target for the host side (issue 11): whatever bytes a drive, a cable or a file delivers, the
// IDE's readers answer or refuse — never crash, hang or grow without bound. The first byte picks the reader:
//   0  the Bds5Session response parser: the rest is the drive's byte stream, fed in chunks split at 0xFF,
//      with commands queued between chunks (prompt detection, error lines, echo stripping)
//   1  a .VAR file (Bds5VariableFile::parse, then its own text must parse to the same assignments)
//   2  a program prepared for download (Bds5ProgramText: comment stripping and the line maps)
//   3  error and prompt lines (parseErrorLine, trailingPrompt) one line at a time
//   4  the Sc750Session frame reader under a running Sc750Download: the rest is the SC750's byte stream
//      (frames, program output, events, refusals), in chunks split at 0xFF with commands, program input
//      and (once) Ctrl C between chunks; the download parses V, W offsets, !04 OFFSET n and refusals
//   5  the Pmc960Session response reader under a running Pmc960Download: prompt detection, #xx decoding,
//      poll answers and the <attn>h checksum answer, in chunks split at 0xFF with commands, polls, editor
//      lines, typed bytes and resynchronisation between chunks
//   6  the RFC 2217 server of servodesk-sim --tcp (issue 21): a device-server client's Telnet stream, in chunks
//      of 1, 7, 3 and 16 bytes in turn (every byte value means something to Telnet); the server's answers must be commands only (no data), answer each option at most once
//      per change, and the data it passes must survive escape() and a second decode unchanged
// The same file is the body of host_parsers_fuzz_replay, which runs the corpus in every CTest build.
#include "serialport/bds5_program_text.h"
#include "serialport/bds5_protocol.h"
#include "serialport/bds5_session.h"
#include "serialport/bds5_variable_file.h"
#include "serialport/link.h"
#include "serialport/pmc960_download.h"
#include "serialport/pmc960_session.h"
#include "serialport/rfc2217.h"
#include "serialport/sc750_download.h"
#include "serialport/sc750_session.h"

#include <QCoreApplication>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <vector>

namespace {

[[noreturn]] void fail(const char* what) {
    std::fprintf(stderr, "host_parsers_fuzz: invariant violated: %s\n", what);
    std::abort();
}

// A link whose far end is the fuzzer: writes vanish, bytes arrive when told. quietMs 0 (the PMC-960's)
// lets a prompt settle at the next processEvents() instead of after real milliseconds.
class FuzzLink final : public serialport::Link {
public:
    explicit FuzzLink(int quietMs = 20) : m_quietMs(quietMs) {}
    void open() override {
        m_open = true;
        emit opened();
    }
    void close() override {
        m_open = false;
        emit closed();
    }
    bool isOpen() const override { return m_open; }
    void write(const QByteArray& bytes) override { m_written += bytes.size(); }
    QString description() const override { return QStringLiteral("fuzz"); }
    int baudRate() const override { return 9600; }
    int quietMs() const override { return m_quietMs; }
    void deliver(const QByteArray& bytes) { emit bytesReceived(bytes); }
    qint64 written() const { return m_written; }

private:
    int m_quietMs;
    bool m_open = false;
    qint64 m_written = 0;
};

// Every request id is answered (finished, answered or failed) at most once.
class AnsweredOnce {
public:
    void operator()(quint64 id) {
        if (!m_ids.insert(id).second) fail("a request was answered twice");
    }

private:
    std::set<quint64> m_ids;
};

void fuzzSession(const QByteArray& stream) {
    FuzzLink link;
    serialport::Bds5Session session(link);
    link.open();
    int chunk = 0;
    for (const QByteArray& part : stream.split('\xff')) {
        link.deliver(part);
        switch (chunk++ % 4) {
        case 0: session.send(QStringLiteral("P X1")); break;
        case 1: session.sendEscape(); break;
        case 2: session.sendRaw("K\r"); break;
        default: session.sendUrgent("\x18"); break;
        }
        QCoreApplication::processEvents(); // timers that are due (silence) fire here
    }
    if (link.written() > 64 * (stream.size() + 16)) fail("the session wrote out of proportion to its input");
}

void fuzzVariableFile(const QString& text) {
    const auto file = serialport::Bds5VariableFile::parse(text);
    const auto again = serialport::Bds5VariableFile::parse(file.toText());
    if (again.toText() != file.toText()) fail(".VAR text does not survive its own round trip");
}

void fuzzProgramText(const QString& text) {
    for (const bool strip : {false, true}) {
        const auto program = serialport::Bds5ProgramText::prepare(text, strip);
        const int editorLines = int(text.count(QLatin1Char('\n'))) + 1;
        for (int line = 1; line <= program.lineCount(); ++line) {
            const int source = program.sourceLine(line);
            if (source < 1 || source > editorLines) fail("a drive line maps outside the editor's text");
            if (program.driveLine(source) != line) fail("editor and drive line maps disagree");
        }
    }
}

void fuzzLines(const QString& text) {
    for (const QString& line : text.split(QLatin1Char('\n'))) {
        (void)serialport::parseErrorLine(line);
        if (const auto prompt = serialport::trailingPrompt(line))
            if (prompt->size() > 4) fail("a prompt longer than any the drive sends");
    }
}

void fuzzSc750(const QByteArray& stream) {
    using namespace serialport;
    FuzzLink link;
    Sc750Session session(link);
    link.open();
    AnsweredOnce answered;
    QObject::connect(&session, &Sc750Session::finished, [&](quint64 id, const Sc750Reply& reply) {
        answered(id);
        if (reply.isError()) fail("an SC750 error answer passed as a result");
    });
    QObject::connect(&session, &Sc750Session::failed, [&](quint64 id, const QString&) { answered(id); });
    Sc750Download download(session, std::vector<std::uint8_t>(100, 0x5A));
    int downloadsFinished = 0;
    QObject::connect(&download, &Sc750Download::progress, [](qint64 sent, qint64 total) {
        if (sent < 0 || sent > total) fail("SC750 download progress outside the .BIN");
    });
    QObject::connect(&download, &Sc750Download::finished, [&](bool, const QString&) { ++downloadsFinished; });
    download.start();
    int chunk = 0;
    int frameEnds = 0;
    for (const QByteArray& part : stream.split('\xff')) {
        link.deliver(part);
        frameEnds += int(part.count('\r'));
        switch (chunk++ % 5) {
        case 0: session.send('G', QStringLiteral("POS")); break;
        case 1: session.send('?', {}, true); break;
        case 2: session.sendProgramInput("12\r\x01"); break;
        case 3: session.logOn(3); break;
        default: chunk == 10 ? session.sendStop() : (void)session.send('P', QStringLiteral("X=1")); break;
        }
        QCoreApplication::processEvents();
    }
    if (downloadsFinished > 1) fail("the SC750 download finished twice");
    // each frame end sends at most one frame (a retry or the next command), as does each chunk's command
    if (link.written() > 256 * (qint64(frameEnds) + chunk + 2)) fail("the SC750 session wrote out of proportion");
}

void fuzzPmc960(const QByteArray& stream) {
    using namespace serialport;
    FuzzLink link(0);
    Pmc960Session session(link);
    link.open();
    AnsweredOnce answered;
    QObject::connect(&session, &Pmc960Session::finished, [&](quint64 id, const Pmc960Response& response) {
        answered(id);
        if (response.error < 0 || response.error > 0xFF) fail("a #xx code outside two hex digits");
        if ((response.error != 0) == response.errorText.isEmpty()) fail("an error code without its text");
    });
    QObject::connect(&session, &Pmc960Session::pollAnswered, [&](quint64 id, char, const QString&) { answered(id); });
    QObject::connect(&session, &Pmc960Session::failed, [&](quint64 id, const QString&) { answered(id); });
    int asyncErrors = 0;
    QObject::connect(&session, &Pmc960Session::asyncError, [&](int code, const QString&) {
        ++asyncErrors;
        if (code < 0 || code > 0xFF) fail("an asynchronous #xx code outside two hex digits");
    });
    Pmc960Download download(session, QStringLiteral("@T\nA3500\nI4000+\n"));
    int downloadsDone = 0;
    QObject::connect(&download, &Pmc960Download::done, [&](const Pmc960DownloadResult& result) {
        ++downloadsDone;
        if (result.ok && result.hostChecksum != result.driveChecksum) fail("a download passed a checksum mismatch");
    });
    download.start();
    int chunk = 0;
    for (const QByteArray& part : stream.split('\xff')) {
        link.deliver(part);
        switch (chunk++ % 7) {
        case 0: session.send("A?"); break;
        case 1: session.poll('g'); break;
        case 2: session.sendExpecting("I+\r", "I+\r\n"); break;
        case 3: session.sendTyped("V?"); break;
        case 4: session.send("A3500\r"); break;
        case 5: session.resynchronise("\x1b"); break;
        default: continue; // the next chunk arrives before the prompt has settled
        }
        QCoreApplication::processEvents(); // a prompt settles here (quietMs 0)
    }
    if (downloadsDone > 1) fail("the PMC-960 download finished twice");
    if (asyncErrors > stream.count('#')) fail("an asynchronous error reported more often than the controller sent it");
    if (link.written() > 64 * (stream.size() + 16)) fail("the PMC-960 session wrote out of proportion");
}

void fuzzRfc2217(const QByteArray& stream) {
    using namespace serialport::rfc2217;
    Server server;
    std::string passed;
    std::size_t replied = 0;
    const std::size_t sizes[] = {1, 7, 3, 16};
    for (std::size_t at = 0, n = 0; at < std::size_t(stream.size()); at += sizes[n++ % 4]) {
        const std::size_t length = std::min(sizes[n % 4], std::size_t(stream.size()) - at);
        std::string reply;
        passed += server.feed(std::string_view(stream.constData() + at, length), reply);
        Decoder check;
        std::vector<Decoder::Command> commands;
        if (!check.feed(reply, commands).empty()) fail("the RFC 2217 server answered with data");
        replied += reply.size();
    }
    // Each answer is at most a subnegotiation as long as the one it answers, or one option for three bytes.
    if (replied > 8 * (std::size_t(stream.size()) + 4)) fail("the RFC 2217 server answered out of proportion");
    if (passed.size() > std::size_t(stream.size())) fail("the RFC 2217 server passed more data than it got");
    Decoder again;
    std::vector<Decoder::Command> none;
    if (again.feed(escape(passed), none) != passed || !none.empty()) fail("escaped data did not decode to itself");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static int argc = 1;
    static char name[] = "host_parsers_fuzz";
    static char* argv[] = {name, nullptr};
    static QCoreApplication app(argc, argv);
    if (size == 0 || size > (1u << 16)) return 0;
    const QByteArray rest(reinterpret_cast<const char*>(data) + 1, qsizetype(size - 1));
    switch (data[0] % 7) {
    case 0: fuzzSession(rest); break;
    case 1: fuzzVariableFile(QString::fromLatin1(rest)); break;
    case 2: fuzzProgramText(QString::fromLatin1(rest)); break;
    case 3: fuzzLines(QString::fromLatin1(rest)); break;
    case 4: fuzzSc750(rest); break;
    case 5: fuzzPmc960(rest); break;
    default: fuzzRfc2217(rest); break;
    }
    return 0;
}
