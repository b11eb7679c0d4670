// Checks what the screenshot tour saved: each PNG exists, has the expected size and real content (many
// colours, not a blank or single-colour window), shows its own view — what its facts file says it shows and,
// for a plot, a trace in the plot area — and the terminal's text shows the sign-on and HELLO, WORLD.
//
// usage: screenshot_check DIR SPEC...
// SPEC:  name.png=WxH[,CHECK]...       e.g. scope-step-response.png=1280x800,dock=Scope,text=Overshoot,plot
//   W, H       the size in pixels, '*' for a side that may vary (at least 100)
//   CHECKs against "name.png.facts", what the tour read from the widgets at the grab (app/tour/shot_facts.h):
//   text=X     some fact's text contains X ("label: Overshoot 12 %" has Overshoot)
//   dock=X     a dock titled exactly X is visible in the shot ("dock: X")
//   title=X    the grabbed window's title contains X ("window: ...X...": main window, dialog, floated dock)
//   status=X   the status bar's message contains X ("status: ...X...")
//   !text=X, !dock=X, !title=X, !status=X    the opposite: no such fact (a dock grabbed alone has no title)
//   plot       the facts name a plot area, and each one is 100x60 pixels or more and holds a trace: 200 or
//              more pixels of a saturated colour (max-min channel >= 60) far from the area's background (its
//              most common colour), over 40 columns or more — grid, axes, cursors and text are grey and do not
//              count, and a coloured marker line is one column or two
// X is compared as written, case-sensitive; it may hold spaces (quote the SPEC in CMake) but no comma.
// Every failure is a line "FAIL: name.png: why"; the exit status is 1 if there was any.
#include "shot_expectations.h"

#include "drive_core/bds5/bds5_drive.h"

#include <QDir>
#include <QFile>
#include <QGuiApplication>
#include <QImage>
#include <QRegularExpression>
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

// The failures of one SPEC, each said once.
int checkShot(const QDir& dir, const QString& spec) {
    const QString name = spec.section(QLatin1Char('='), 0, 0);
    const QStringList checks = spec.section(QLatin1Char('='), 1).split(QLatin1Char(','));
    const QStringList size = checks.first().split(QLatin1Char('x'));
    QImage image(dir.filePath(name));
    if (image.isNull()) return fail(QStringLiteral("%1: missing or not an image").arg(name));
    image = image.convertToFormat(QImage::Format_ARGB32);
    if (size.size() != 2 || !sideMatches(size[0], image.width()) || !sideMatches(size[1], image.height()))
        return fail(QStringLiteral("%1: is %2x%3, expected %4")
                        .arg(name)
                        .arg(image.width())
                        .arg(image.height())
                        .arg(checks.first()));
    const int colours = distinctColours(image, kMinColours);
    if (colours < kMinColours)
        return fail(QStringLiteral("%1: has only %2 colours: blank or unpainted").arg(name).arg(colours));

    QFile factsFile(dir.filePath(name + QStringLiteral(".facts")));
    if (checks.size() > 1 && !factsFile.open(QIODevice::ReadOnly))
        return fail(QStringLiteral("%1: %2 is missing").arg(name, factsFile.fileName()));
    const QStringList facts = QString::fromUtf8(factsFile.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    int failures = 0;
    for (const QString& why : unmetExpectations(checks.mid(1), facts, image))
        failures += fail(QStringLiteral("%1: %2").arg(name, why));
    if (failures == 0)
        QTextStream(stdout) << "ok " << name << ' ' << image.width() << 'x' << image.height() << ' '
                            << checks.mid(1).join(QLatin1Char(',')) << Qt::endl;
    return failures;
}

// The terminal's own text, saved by the tour: pixels alone cannot say the drive answered.
int checkTerminalText(const QDir& dir) {
    QFile terminalText(dir.filePath(QStringLiteral("terminal.txt")));
    if (!terminalText.open(QIODevice::ReadOnly)) return fail(QStringLiteral("terminal.txt is missing"));
    const QStringList lines = QString::fromUtf8(terminalText.readAll()).split(QLatin1Char('\n'));
    int failures = 0;
    if (!lines.join(QLatin1Char('\n')).contains(QString::fromLatin1(drive_core::bds5::kSignOn)))
        failures += fail(QStringLiteral("the terminal does not show the sign-on"));
    const qsizetype hello = lines.indexOf(QStringLiteral("HELLO, WORLD"));
    if (hello < 1 || lines.value(hello - 1) != QLatin1String("-->P \"HELLO, WORLD\"") ||
        lines.value(hello + 1) != QLatin1String("-->"))
        failures +=
            fail(QStringLiteral("the terminal does not show the HELLO, WORLD exchange:\n%1").arg(lines.join('\n')));
    return failures;
}

} // namespace

int main(int argc, char** argv) {
    QGuiApplication app(argc, argv);
    const QStringList args = QCoreApplication::arguments().mid(1);
    if (args.size() < 2) return fail(QStringLiteral("usage: screenshot_check DIR name.png=WxH[,CHECK]..."));
    const QDir dir(args.first());
    int failures = 0;
    for (const QString& spec : args.mid(1)) failures += checkShot(dir, spec);
    // terminal.txt goes with the terminal's shot (a refusal test's folder holds neither).
    if (!args.filter(QRegularExpression(QStringLiteral("^terminal\\.png="))).isEmpty())
        failures += checkTerminalText(dir);
    return failures == 0 ? 0 : 1;
}
