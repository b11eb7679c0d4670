// libFuzzer target for the host side (issue 11): whatever bytes a drive, a cable or a file delivers, the
// IDE's readers answer or refuse — never crash, hang or grow without bound. The first byte picks the reader:
//   0  the Bds5Session response parser: the rest is the drive's byte stream, fed in chunks split at 0xFF,
//      with commands queued between chunks (prompt detection, error lines, echo stripping)
//   1  a .VAR file (Bds5VariableFile::parse, then its own text must parse to the same assignments)
//   2  a program prepared for download (Bds5ProgramText: comment stripping and the line maps)
//   3  error and prompt lines (parseErrorLine, trailingPrompt) one line at a time
// The same file is the body of host_parsers_fuzz_replay, which runs the corpus in every CTest build.
#include "serialport/bds5_program_text.h"
#include "serialport/bds5_protocol.h"
#include "serialport/bds5_session.h"
#include "serialport/bds5_variable_file.h"
#include "serialport/link.h"

#include <QCoreApplication>

#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace {

[[noreturn]] void fail(const char* what) {
    std::fprintf(stderr, "host_parsers_fuzz: invariant violated: %s\n", what);
    std::abort();
}

// A link whose far end is the fuzzer: writes vanish, bytes arrive when told.
class FuzzLink final : public serialport::Link {
public:
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
    void deliver(const QByteArray& bytes) { emit bytesReceived(bytes); }
    qint64 written() const { return m_written; }

private:
    bool m_open = false;
    qint64 m_written = 0;
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

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static int argc = 1;
    static char name[] = "host_parsers_fuzz";
    static char* argv[] = {name, nullptr};
    static QCoreApplication app(argc, argv);
    if (size == 0 || size > (1u << 16)) return 0;
    const QByteArray rest(reinterpret_cast<const char*>(data) + 1, qsizetype(size - 1));
    switch (data[0] % 4) {
    case 0: fuzzSession(rest); break;
    case 1: fuzzVariableFile(QString::fromLatin1(rest)); break;
    case 2: fuzzProgramText(QString::fromLatin1(rest)); break;
    default: fuzzLines(QString::fromLatin1(rest)); break;
    }
    return 0;
}
