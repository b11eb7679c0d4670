// The Scope dock as a servo engineer reads it (issue 22), with a loaded capture file of a 50 Hz oscillation
// (VFB in VEL, ICMD in %, PE in POS): cursors A and B placed and moved by keys read the period as 1/Δt = 50 Hz;
// each unit has its own labelled, coloured, auto-scaled value axis (or one shared); the XY tab plots one
// channel against another; and Save CSV / Export Plot write the visible range only or the whole record.
#include "app/main_window.h"
#include "app/scope/scope_controller.h"
#include "app/scope/scope_export.h"
#include "app/scope/scope_view.h"

#include "scope/capture_csv.h"
#include "scope/scope_plot.h"
#include "scope/xy_plot.h"

#include <qcustomplot.h>

#include <QComboBox>
#include <QFile>
#include <QLabel>
#include <QMenu>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QToolBar>

#include <cmath>

using app::MainWindow;

namespace {
constexpr double kInterval_s = 0.0005; // 2 kHz sampling
constexpr int kSamples = 400;          // 200 ms: ten periods at 50 Hz

// VFB = 1000 sin(2π 50 t) rpm-like, ICMD = 5 cos(2π 50 t) %, PE = 20 sin: units far apart, on purpose.
scope::Capture oscillation() {
    scope::Capture c;
    c.interval_s = kInterval_s;
    c.channels = {{"VFB", "VEL", {}}, {"ICMD", "%", {}}, {"PE", "POS", {}}};
    for (int i = 0; i < kSamples; ++i) {
        const double phase = 2 * M_PI * 50 * i * kInterval_s;
        c.channels[0].values.push_back(std::round(1000 * std::sin(phase) * 1000) / 1000);
        c.channels[1].values.push_back(std::round(5 * std::cos(phase) * 1000) / 1000);
        c.channels[2].values.push_back(std::round(20 * std::sin(phase) * 1000) / 1000);
    }
    return c;
}

QString readoutLine(const scope::ScopePlot* plot) {
    const auto* label = plot->findChild<QLabel*>(QStringLiteral("cursorReadout"));
    return label ? label->text() : QStringLiteral("(no readout label)");
}

QAction* toolBarAction(app::ScopeView* view, const QString& objectName) {
    for (QAction* a : view->toolBar()->actions())
        if (a->objectName() == objectName) return a;
    return nullptr;
}

QAction* rangeChoice(app::ScopeController& scope, const QString& objectName) {
    auto* menu = scope.menu()->findChild<QMenu*>(QStringLiteral("exportRangeMenu"));
    if (!menu) return nullptr;
    for (QAction* a : menu->actions())
        if (a->objectName() == objectName) return a;
    return nullptr;
}

QStringList dataRows(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return {};
    QStringList lines = QString::fromLatin1(file.readAll()).split(QStringLiteral("\r\n"), Qt::SkipEmptyParts);
    return lines.mid(2); // the RECORD line and the column titles
}

// Points of the first channel's polyline in an exported SVG.
int svgPoints(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return -1;
    const QString svg = QString::fromUtf8(file.readAll());
    const qsizetype at = svg.indexOf(QStringLiteral("points=\""));
    if (at < 0) return -1;
    const qsizetype end = svg.indexOf(QLatin1Char('"'), at + 8);
    return int(svg.mid(at + 8, end - at - 8).split(QLatin1Char(' '), Qt::SkipEmptyParts).size());
}

struct Window {
    MainWindow window;
    QTemporaryDir dir;
    app::ScopeController& scope = window.scopeController();
    Window() { window.show(); }
    // Scope > From Disk, as a user opens a recorded file.
    bool load(const scope::Capture& capture) {
        const QString path = dir.filePath(QStringLiteral("oscillation.csv"));
        QFile file(path);
        if (!file.open(QIODevice::WriteOnly) || file.write(QByteArray::fromStdString(scope::writeCsv(capture))) <= 0)
            return false;
        file.close();
        return scope.loadCsv(path) && QTest::qWaitForWindowExposed(scope.view()->plot());
    }
};
} // namespace

class ScopeCursorsXyTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskScopeCursorsXyTest"));
    }

    // Peaks at 5 ms and 25 ms: A there by the API, B moved there from 20 ms by ten Shift+Right (one sample each).
    void keyboardCursorsReadTheOscillationsFrequency() {
        Window w;
        QVERIFY(w.load(oscillation()));
        scope::ScopePlot* plot = w.scope.view()->plot();
        QCustomPlot* custom = plot->customPlot();
        custom->setFocus();
        QTest::keyClick(custom, Qt::Key_C); // C: both cursors into view
        QVERIFY(plot->cursorsVisible());
        plot->setCursors(0.005, 0.020);
        QTest::keyClick(custom, Qt::Key_Space); // B is the one the keys move now
        QCOMPARE(plot->activeCursor(), 1);
        for (int i = 0; i < 10; ++i) QTest::keyClick(custom, Qt::Key_Right, Qt::ShiftModifier);
        QVERIFY2(std::abs(plot->readout().second_s - 0.025) < 1e-9, qPrintable(readoutLine(plot)));
        const QString line = readoutLine(plot);
        QVERIFY2(line.contains(QStringLiteral("\u0394t 20.00 ms   1/\u0394t 50.0 Hz")), qPrintable(line));
        QVERIFY2(line.contains(QStringLiteral("VFB 1000 \u2192 1000  \u0394y 0 VEL")), qPrintable(line));
        QVERIFY2(line.contains(QStringLiteral("ICMD 0 \u2192 0  \u0394y 0 %")), qPrintable(line));
        // The keys are told where a user looks for them.
        QAction* cursors = nullptr;
        for (QAction* a : w.scope.view()->toolBar()->actions())
            if (a->text() == QStringLiteral("Cursors")) cursors = a;
        QVERIFY(cursors && cursors->toolTip().contains(QStringLiteral("Shift+Left/Right")));
    }

    // Three units, three value axes: left, right, left; each labelled with its channel and unit, in its
    // channel's colour, scaled to its own channel (the 5 % current is not flattened by the 1000 VEL velocity).
    void eachUnitHasItsOwnAxisOrAllShareOne() {
        Window w;
        QVERIFY(w.load(oscillation()));
        scope::ScopePlot* plot = w.scope.view()->plot();
        const QList<QCPAxis*> axes = plot->valueAxes();
        QCOMPARE(axes.size(), 3);
        QCOMPARE(axes[0]->label(), QStringLiteral("VFB [VEL]"));
        QCOMPARE(axes[1]->label(), QStringLiteral("ICMD [%]"));
        QCOMPARE(axes[2]->label(), QStringLiteral("PE [POS]"));
        QCOMPARE(axes[0]->axisType(), QCPAxis::atLeft);
        QCOMPARE(axes[1]->axisType(), QCPAxis::atRight);
        for (QCPAxis* axis : axes) {
            QVERIFY(axis->visible());
            QCOMPARE(axis->graphs().size(), 1);
            QCOMPARE(axis->labelColor(), axis->graphs().first()->pen().color());
        }
        QVERIFY2(axes[1]->range().upper > 5 && axes[1]->range().upper < 7, "ICMD's axis fits its 5 %");
        QVERIFY2(axes[0]->range().upper > 1000 && axes[0]->range().upper < 1200, "VFB's axis fits its 1000");

        QAction* perUnit = toolBarAction(w.scope.view(), QStringLiteral("axisPerUnit"));
        QVERIFY(perUnit && perUnit->isChecked());
        perUnit->trigger(); // off: one shared axis
        QCOMPARE(plot->valueAxes().size(), 1);
        QCOMPARE(plot->valueAxes()[0]->label(), QStringLiteral("VFB [VEL], ICMD [%], PE [POS]"));
        QVERIFY(plot->valueAxes()[0]->range().upper > 1000);
        QVERIFY(!axes[1]->visible());
        perUnit->trigger();
        QCOMPARE(plot->valueAxes().size(), 3);
        QVERIFY(plot->valueAxes()[1]->range().upper < 7); // auto-scaled per axis again
    }

    // The XY tab: PE against VFB, point for point, axes titled with the channels; the choice survives a new
    // capture of the same channels.
    void xyTabPlotsOneChannelAgainstAnother() {
        Window w;
        const scope::Capture capture = oscillation();
        QVERIFY(w.load(capture));
        app::ScopeView* view = w.scope.view();
        scope::XyPlot* xy = view->xyPlot();
        view->tabs()->setCurrentWidget(xy);
        QVERIFY(QTest::qWaitForWindowExposed(xy));
        xy->xChooser()->setCurrentIndex(xy->xChooser()->findText(QStringLiteral("VFB [VEL]")));
        xy->yChooser()->setCurrentIndex(xy->yChooser()->findText(QStringLiteral("PE [POS]")));
        const auto data = xy->curve()->data();
        QCOMPARE(data->size(), kSamples);
        for (int i = 0; i < kSamples; ++i) {
            QCOMPARE(data->at(i)->key, capture.channels[0].values[std::size_t(i)]);
            QCOMPARE(data->at(i)->value, capture.channels[2].values[std::size_t(i)]);
        }
        QCOMPARE(xy->customPlot()->xAxis->label(), QStringLiteral("VFB [VEL]"));
        QCOMPARE(xy->customPlot()->yAxis->label(), QStringLiteral("PE [POS]"));
        QVERIFY(w.load(capture)); // opened again: still PE against VFB
        QCOMPARE(xy->yChooser()->currentText(), QStringLiteral("PE [POS]"));
        QCOMPARE(xy->curve()->data()->at(10)->value, capture.channels[2].values[10]);
    }

    // Zoomed to 50..100 ms: Export Range > Visible Range Only writes the 101 samples inside it (0.5 ms apart),
    // which load back at their times; Whole Record writes all 400. The plot files follow the same choice.
    void exportsTheVisibleRangeOrTheWholeRecord() {
        Window w;
        const scope::Capture capture = oscillation();
        QVERIFY(w.load(capture));
        QCustomPlot* custom = w.scope.view()->plot()->customPlot();
        custom->xAxis->setRange(0.050, 0.100);
        QAction* visible = rangeChoice(w.scope, QStringLiteral("exportVisibleRange"));
        QAction* whole = rangeChoice(w.scope, QStringLiteral("exportWholeRecord"));
        QVERIFY(visible && whole && whole->isChecked());
        visible->trigger();
        QCOMPARE(w.scope.exporter()->range(), app::ExportRange::VisibleRange);

        const QString part = w.dir.filePath(QStringLiteral("part.csv"));
        QVERIFY(w.scope.saveCsv(part));
        QVERIFY(w.window.statusBar()->currentMessage().contains(QStringLiteral("(visible range)")));
        const QStringList rows = dataRows(part);
        QCOMPARE(rows.size(), 101);
        QVERIFY2(rows.first().startsWith(QStringLiteral("0.05,")), qPrintable(rows.first()));
        QVERIFY2(rows.last().startsWith(QStringLiteral("0.1,")), qPrintable(rows.last()));
        QVERIFY(w.scope.loadCsv(part));
        const scope::Capture back = *w.scope.lastCapture();
        QCOMPARE(back.sampleCount(), std::size_t(101));
        QCOMPARE(back.start_s, 0.05);
        QCOMPARE(back.channels[0].values.front(), capture.channels[0].values[100]);
        QCOMPARE(back.channels[2].values.back(), capture.channels[2].values[200]);
        QCOMPARE(w.scope.view()->plot()->store().channel(0).samples.front().time_s, 0.05); // plotted where it was

        // The plot files: the SVG draws the visible samples (and one each side), or every one.
        QVERIFY(w.scope.loadCsv(w.dir.filePath(QStringLiteral("oscillation.csv"))));
        custom->xAxis->setRange(0.050, 0.100);
        const QString partSvg = w.dir.filePath(QStringLiteral("part.svg"));
        QVERIFY(w.scope.exportTo(partSvg));
        QCOMPARE(svgPoints(partSvg), 103);
        whole->trigger();
        const QString all = w.dir.filePath(QStringLiteral("all.csv"));
        QVERIFY(w.scope.saveCsv(all));
        QCOMPARE(dataRows(all).size(), kSamples);
        const QString allSvg = w.dir.filePath(QStringLiteral("all.svg"));
        QVERIFY(w.scope.exportTo(allSvg));
        QCOMPARE(svgPoints(allSvg), kSamples);
        QCOMPARE(custom->xAxis->range().lower, 0.050); // the user's zoom is back after a whole-record export
        QCOMPARE(custom->xAxis->range().upper, 0.100);
        const QString png = w.dir.filePath(QStringLiteral("all.png"));
        QVERIFY(w.scope.exportTo(png));
        QVERIFY(!QImage(png).isNull());
    }
};

QTEST_MAIN(ScopeCursorsXyTest)
#include "scope_cursors_xy_test.moc"
