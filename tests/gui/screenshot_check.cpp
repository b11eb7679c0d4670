// Checks what the screenshot tour saved: each PNG exists, has the expected size and real content (many
// colours, not a blank or single-colour window), and the terminal's text shows the sign-on and HELLO, WORLD.
// usage: screenshot_check DIR name.png=WxH ...   ('*' for a side that may vary)
#include "drive_core/bds5/bds5_drive.h"

#include <QDir>
#include <QFile>
#include <QGuiApplication>
#include <QImage>
#include <QSet>
#include <QTextStream>

namespace {

constexpr int kMinColours = 16;
constexpr int kMinSide = 100;

int fail(const QString& why) {
    QTextStream(stderr) << "FAIL: " << why << Qt::endl;
    return 1;
}

int distinctColours(const QImage& image, int enough) {
    QSet<QRgb> seen;
    for (int y = 0; y < image.height(); ++y) {
        const auto* line = reinterpret_cast<const QRgb*>(image.constScanLine(y));
        for (int x = 0; x < image.width(); ++x) {
            seen.insert(line[x]);
            if (seen.size() >= enough) return int(seen.size());
        }
    }
    return int(seen.size());
}

// "1280" must match exactly, "*" matches any size of at least kMinSide.
bool sideMatches(const QString& expected, int actual) {
    return expected == QLatin1String("*") ? actual >= kMinSide : expected.toInt() == actual;
}

} // namespace

int main(int argc, char** argv) {
    QGuiApplication app(argc, argv);
    const QStringList args = QCoreApplication::arguments().mid(1);
    if (args.size() < 2) return fail(QStringLiteral("usage: screenshot_check DIR name.png=WxH ..."));
    const QDir dir(args.first());
    int failures = 0;
    for (const QString& spec : args.mid(1)) {
        const QString name = spec.section(QLatin1Char('='), 0, 0);
        const QStringList size = spec.section(QLatin1Char('='), 1).split(QLatin1Char('x'));
        const QString path = dir.filePath(name);
        QImage image(path);
        if (image.isNull()) {
            failures += fail(QStringLiteral("%1 is missing or not an image").arg(path));
            continue;
        }
        image = image.convertToFormat(QImage::Format_ARGB32);
        if (size.size() != 2 || !sideMatches(size[0], image.width()) ||
            !sideMatches(size[1], image.height())) {
            failures += fail(QStringLiteral("%1 is %2x%3, expected %4")
                                 .arg(name)
                                 .arg(image.width())
                                 .arg(image.height())
                                 .arg(spec.section('=', 1)));
            continue;
        }
        const int colours = distinctColours(image, kMinColours);
        if (colours < kMinColours) {
            failures +=
                fail(QStringLiteral("%1 has only %2 colours: blank or unpainted").arg(name).arg(colours));
            continue;
        }
        QTextStream(stdout) << "ok " << name << ' ' << image.width() << 'x' << image.height() << Qt::endl;
    }

    // The terminal's own text, saved by the tour: pixels alone cannot say the drive answered.
    QFile terminalText(dir.filePath(QStringLiteral("terminal.txt")));
    if (!terminalText.open(QIODevice::ReadOnly)) return fail(QStringLiteral("terminal.txt is missing"));
    const QStringList lines = QString::fromUtf8(terminalText.readAll()).split(QLatin1Char('\n'));
    if (!lines.join(QLatin1Char('\n')).contains(QString::fromLatin1(drive_core::bds5::kSignOn)))
        failures += fail(QStringLiteral("the terminal does not show the sign-on"));
    const qsizetype hello = lines.indexOf(QStringLiteral("HELLO, WORLD"));
    if (hello < 1 || lines.value(hello - 1) != QLatin1String("-->P \"HELLO, WORLD\"") ||
        lines.value(hello + 1) != QLatin1String("-->"))
        failures += fail(QStringLiteral("the terminal does not show the HELLO, WORLD exchange:\n%1")
                             .arg(lines.join('\n')));
    return failures == 0 ? 0 : 1;
}
