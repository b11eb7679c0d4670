// The scope's cursor readout follows the trace (issue 19): after a new capture it reads the new samples
// where the cursors already stand, and live data update it as they arrive — no cursor has to be dragged.
#include "scope/scope_plot.h"

#include <QLabel>
#include <QTest>

namespace {
scope::Capture constantVcmd(double value, const char* title) {
    scope::Capture capture;
    capture.interval_s = 0.001;
    capture.title = title;
    capture.channels = {{"VCMD", "VEL", std::vector<double>(200, value)}};
    return capture;
}

QString readoutLine(const scope::ScopePlot& plot) {
    const auto* label = plot.findChild<QLabel*>(QStringLiteral("cursorReadout"));
    return label ? label->text() : QStringLiteral("(no readout label)");
}
} // namespace

class ScopeReadoutTest : public QObject {
    Q_OBJECT
private slots:
    // Run 1 had VCMD 0 (a refused move); run 2 is at 1000: the line says 1000, not "VCMD 0 → 0".
    void aNewCaptureUpdatesTheReadoutWhereTheCursorsStand() {
        scope::ScopePlot plot;
        plot.show();
        plot.showCapture(constantVcmd(0, "Run 1"));
        QVERIFY(plot.cursorsVisible());
        QVERIFY2(readoutLine(plot).contains(QStringLiteral("VCMD 0 \u2192 0")), qPrintable(readoutLine(plot)));
        plot.showCapture(constantVcmd(1000, "Run 2"), true); // same length: the cursors stay where they are
        QVERIFY2(readoutLine(plot).contains(QStringLiteral("VCMD 1000 \u2192 1000")), qPrintable(readoutLine(plot)));
        QCOMPARE(plot.readout().rows.at(0).atFirst, 1000.0);
    }

    // Live samples (appendLive) reach the line with the graphs, on the plot's coalescing timer.
    void liveDataUpdateTheReadout() {
        scope::ScopePlot plot;
        plot.show();
        plot.beginLive({{"PFB", "POS"}});
        plot.setCursors(0.5, 3.0);
        for (int i = 0; i <= 20; ++i) plot.appendLive(0, 0.1 * i, 100.0 * i); // PFB = 1000 x t, to 2 s
        // The second cursor is past the samples so far: it reads the last one.
        QTRY_VERIFY2_WITH_TIMEOUT(readoutLine(plot).contains(QStringLiteral("PFB 500 \u2192 2000")),
                                  qPrintable(readoutLine(plot)), 30000);
        for (int i = 21; i <= 30; ++i) plot.appendLive(0, 0.1 * i, 100.0 * i); // to 3 s: the cursors stay
        QTRY_VERIFY2_WITH_TIMEOUT(readoutLine(plot).contains(QStringLiteral("PFB 500 \u2192 3000")),
                                  qPrintable(readoutLine(plot)), 30000);
    }
};

QTEST_MAIN(ScopeReadoutTest)
#include "scope_readout_test.moc"
