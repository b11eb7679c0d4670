// libFuzzer target for the scope's and the terminal's files (issue 11): whatever a .CSV, a PLAY listing or a
// .CAP holds, the readers answer or refuse with a reason — never crash, hang or change data on a round
// trip. The first byte picks the reader:
//   0  a .CSV (scope::readCsv): a capture it accepts, written again (writeCsv), reads back to the same text
//   1  a PLAY listing as the scope reads it (scope::parsePlay), one line per LF
//   2  PLAY copies as the drive's answer (Bds5PlayListing): copies split at 0xFF, never more lines than
//      the header asks for, and an accepted listing is one of exactly the width the drive prints
//   3  a .CAP (CaptureLog::loadCap from a file): kept byte for byte (capBytes) and shown (transcript)
// The same file is the body of capture_files_fuzz_replay, which runs the corpus in every CTest build.
#include "app/drive/capture_log.h"
#include "scope/capture_csv.h"
#include "scope/play_parser.h"
#include "serialport/bds5_play_listing.h"

#include <QCoreApplication>
#include <QFile>
#include <QTemporaryDir>

#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace {

[[noreturn]] void fail(const char* what) {
    std::fprintf(stderr, "capture_files_fuzz: invariant violated: %s\n", what);
    std::abort();
}

void fuzzCsv(const std::string& text) {
    const scope::CsvReadResult read = scope::readCsv(text);
    if (!read.capture) {
        if (read.error.empty()) fail("a refused .CSV without a reason");
        return;
    }
    const std::string written = scope::writeCsv(*read.capture);
    const scope::CsvReadResult again = scope::readCsv(written);
    if (!again.capture) fail("ServoDesk cannot read the .CSV it wrote");
    if (scope::writeCsv(*again.capture) != written) fail(".CSV text does not survive its own round trip");
    if (again.capture->channels.size() != read.capture->channels.size()) fail(".CSV round trip lost channels");
}

void fuzzPlay(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= text.size(); ++i)
        if (i == text.size() || text[i] == '\n') {
            lines.push_back(text.substr(start, i - start));
            start = i + 1;
        }
    const scope::PlayParseResult result = scope::parsePlay(lines);
    if (!result.capture && result.error.empty()) fail("a refused PLAY listing without a reason");
    if (result.capture && result.capture->channels.size() > 4) fail("more than 4 channels from PLAY");
}

void fuzzPlayCopies(const QByteArray& bytes) {
    // The set-up comes from the first two bytes: 1-64 samples of 1-4 variables.
    if (bytes.size() < 2) return;
    const int samples = 1 + (quint8(bytes[0]) % 64);
    const int variables = 1 + (quint8(bytes[1]) % 4);
    static const char* const kNames[] = {"VCMD", "VFB", "PFB", "ICMD"};
    QString header = QStringLiteral("RECORD %1 1").arg(samples);
    for (int v = 0; v < variables; ++v) header += QLatin1Char(' ') + QLatin1String(kNames[v]);
    serialport::Bds5PlayListing listing(header, samples, variables);
    listing.setTrustCleanCopy(bytes.size() % 2 == 0);
    for (const QByteArray& copy : bytes.mid(2).split('\xff')) {
        if (copy == "lost") listing.addLostCopy();
        else listing.addCopy(QString::fromLatin1(copy), copy.startsWith('!'));
        if (listing.samplesAgreed() > samples) fail("more samples agreed than recorded");
        if (!listing.complete()) continue;
        const QStringList lines = listing.lines();
        if (lines.size() != samples + 1 || lines.first() != header) fail("an accepted listing of the wrong shape");
        for (qsizetype i = 1; i < lines.size(); ++i)
            if (lines[i].size() != 12 * variables) fail("an accepted sample line of the wrong width");
    }
}

void fuzzCap(const QByteArray& bytes) {
    static QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("fuzz.CAP"));
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate)) fail("cannot write the temporary .CAP");
    file.write(bytes);
    file.close();
    app::CaptureLog log;
    if (!log.loadCap(path).isEmpty()) fail("a readable .CAP was refused");
    if (log.capBytes() != bytes) fail(".CAP bytes changed on loading");
    if (log.receivedBytes() != bytes.size()) fail(".CAP size miscounted");
    (void)log.transcript();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static int argc = 1;
    static char name[] = "capture_files_fuzz";
    static char* argv[] = {name, nullptr};
    static QCoreApplication app(argc, argv);
    if (size == 0 || size > (1u << 16)) return 0;
    const QByteArray rest(reinterpret_cast<const char*>(data) + 1, qsizetype(size - 1));
    switch (data[0] % 4) {
    case 0: fuzzCsv(rest.toStdString()); break;
    case 1: fuzzPlay(rest.toStdString()); break;
    case 2: fuzzPlayCopies(rest); break;
    default: fuzzCap(rest); break;
    }
    return 0;
}
