// Math channels in the Scope dock (issue 22): a capture opened from disk, A - B and d/dt added with the Math
// dialog as a user would, the plotted values against their closed forms and the units the user reads; the
// following error refused, with why, when command and feedback are in different units; the math channels
// kept and recomputed for the next capture of the same channels, removed on request, and in the saved .CSV.
#include "app/main_window.h"
#include "app/scope/math_channel_dialog.h"
#include "app/scope/scope_controller.h"
#include "app/scope/scope_view.h"

#include "scope/capture_csv.h"
#include "scope/scope_plot.h"

#include <qcustomplot.h>

#include <QDialogButtonBox>
#include <QFile>
#include <QPushButton>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using app::MathChannelDialog;
using scope::MathOp;

namespace {

constexpr double kInterval_s = 0.002;

// PCMD ramps at `slope` counts a sample; PFB lags it by a wobble; VFB is a velocity (another unit).
scope::Capture ramp(double slope) {
    scope::Capture c;
    c.interval_s = kInterval_s;
    c.channels = {{"PCMD", "POS", {}}, {"PFB", "POS", {}}, {"VFB", "VEL", {}}};
    for (int i = 0; i < 200; ++i) {
        c.channels[0].values.push_back(slope * i);
        c.channels[1].values.push_back(slope * i - 4 - i % 5);
        c.channels[2].values.push_back(100);
    }
    return c;
}

bool writeFile(const QString& path, const scope::Capture& capture) {
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(QByteArray::fromStdString(scope::writeCsv(capture))) > 0;
}

// What the user reads on the plot: every visible axis label and legend entry.
QStringList plotTexts(QCustomPlot* plot) {
    QStringList texts;
    for (QCPAxisRect* rect : plot->axisRects())
        for (QCPAxis* axis : rect->axes())
            if (axis->visible() && !axis->label().isEmpty()) texts << axis->label();
    for (int i = 0; i < plot->legend->itemCount(); ++i)
        if (auto* item = qobject_cast<QCPPlottableLegendItem*>(plot->legend->item(i)))
            texts << item->plottable()->name();
    return texts;
}

// The label of the value axis a channel is drawn against: "PCMD, PFB, PCMD-PFB [POS]" (one axis per unit).
QString axisLabelOf(const scope::ScopePlot* plot, const QString& channel) {
    for (const QString& text : plotTexts(plot->customPlot()))
        if (text.endsWith(QLatin1Char(']')) && (text.startsWith(channel + QLatin1Char(' ')) ||
                                                 text.contains(QStringLiteral(", ") + channel + QLatin1Char(' ')) ||
                                                 text.startsWith(channel + QLatin1Char(','))))
            return text;
    return {};
}

std::vector<double> plotted(const scope::ScopePlot* plot, const std::string& name) {
    std::vector<double> values;
    if (const auto index = plot->store().find(name))
        for (const scope::Sample& s : plot->store().channel(*index).samples) values.push_back(s.value);
    return values;
}

// Adds what the dialog shows with its Add button, as a click would.
void pressAdd(MathChannelDialog* dialog) {
    for (QPushButton* b : dialog->findChildren<QPushButton*>())
        if (b->text() == QStringLiteral("&Add")) return b->click();
    QFAIL("no Add button");
}

} // namespace

class ScopeMathTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ServoDesk"));
        QCoreApplication::setApplicationName(QStringLiteral("ServoDeskScopeMathTest"));
    }

    void differenceAndDerivativeArePlottedWithTheirUnitsAndKeptForTheNextCapture() {
        app::MainWindow window;
        window.show();
        app::ScopeController& controller = window.scopeController();
        app::ScopeView* view = controller.view();
        QTemporaryDir dir;
        const QString first = dir.filePath(QStringLiteral("first.csv"));
        QVERIFY(writeFile(first, ramp(3)));
        QVERIFY(controller.loadCsv(first));

        MathChannelDialog* dialog = view->openMathDialog();
        dialog->choose(MathOp::Difference, QStringLiteral("PCMD"), QStringLiteral("PFB"));
        QCOMPARE(dialog->preview(), QStringLiteral("New channel: PCMD-PFB [POS]"));
        pressAdd(dialog);
        dialog = view->openMathDialog();
        dialog->choose(MathOp::Derivative, QStringLiteral("PCMD"));
        QCOMPARE(dialog->preview(), QStringLiteral("New channel: d/dt(PCMD) [POS/s]"));
        pressAdd(dialog);

        // A - B sample by sample is the wobble 4 + i % 5; the derivative of a ramp of 3 counts per 2 ms is
        // 1500 counts/s everywhere, ends included.
        scope::ScopePlot* plot = view->plot();
        const std::vector<double> error = plotted(plot, "PCMD-PFB");
        QCOMPARE(error.size(), std::size_t(200));
        for (std::size_t i = 0; i < error.size(); ++i) QCOMPARE(error[i], 4.0 + double(i % 5));
        const std::vector<double> slope = plotted(plot, "d/dt(PCMD)");
        QCOMPARE(slope.size(), std::size_t(200));
        for (double v : slope) QVERIFY2(std::abs(v - 1500) < 1e-6, qPrintable(QString::number(v)));
        const QString texts = plotTexts(plot->customPlot()).join(QStringLiteral(" | "));
        QVERIFY2(axisLabelOf(plot, QStringLiteral("PCMD-PFB")).endsWith(QStringLiteral(" [POS]")), qPrintable(texts));
        QVERIFY2(axisLabelOf(plot, QStringLiteral("d/dt(PCMD)")).endsWith(QStringLiteral(" [POS/s]")), qPrintable(texts));
        QVERIFY2(texts.contains(QStringLiteral("d/dt(PCMD)")), qPrintable(texts)); // in the legend

        // The next capture of the same channels: both stay, recomputed (a ramp of 5 a sample: 2500/s).
        const QString second = dir.filePath(QStringLiteral("second.csv"));
        QVERIFY(writeFile(second, ramp(5)));
        QVERIFY(controller.loadCsv(second));
        QCOMPARE(plot->overlayCount(), 1);
        for (double v : plotted(plot, "d/dt(PCMD)")) QVERIFY2(std::abs(v - 2500) < 1e-6, qPrintable(QString::number(v)));
        QCOMPARE(plotted(plot, "PCMD-PFB").size(), std::size_t(200));

        // Saved with the capture's channels, in the plot's order and units.
        const QString saved = dir.filePath(QStringLiteral("saved.csv"));
        QVERIFY(controller.saveCsv(saved));
        QFile file(saved);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const auto read = scope::readCsv(file.readAll().toStdString());
        QVERIFY2(read.capture, read.error.c_str());
        QCOMPARE(read.capture->channels.size(), std::size_t(5));
        QCOMPARE(read.capture->channels[4].name, std::string("d/dt(PCMD)"));
        QCOMPARE(read.capture->channels[4].unit, std::string("POS/s"));
        QVERIFY(std::abs(read.capture->channels[4].values[100] - 2500) < 1e-6);

        // Removed: gone from the plot, the overlay of the first capture kept.
        QVERIFY(view->removeMathChannel(QStringLiteral("PCMD-PFB")));
        QVERIFY(plotted(plot, "PCMD-PFB").empty());
        QCOMPARE(plot->overlayCount(), 1);
        QVERIFY(!plotTexts(plot->customPlot()).join(QLatin1Char('|')).contains(QStringLiteral("PCMD-PFB")));
        QCOMPARE(plotted(plot, "d/dt(PCMD)").size(), std::size_t(200));
    }

    void followingErrorOfAPositionAndAVelocityIsRefusedWithWhy() {
        app::MainWindow window;
        window.show();
        app::ScopeController& controller = window.scopeController();
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("ramp.csv"));
        QVERIFY(writeFile(path, ramp(3)));
        QVERIFY(controller.loadCsv(path));

        MathChannelDialog* dialog = controller.view()->openMathDialog();
        dialog->choose(MathOp::FollowingError, QStringLiteral("PCMD"), QStringLiteral("VFB"));
        QCOMPARE(dialog->preview(), QStringLiteral("Cannot add: following error of PCMD (POS) and VFB (VEL): the units "
                                                   "differ. A following error compares a command with its own "
                                                   "feedback: choose two channels in the same unit."));
        QVERIFY(!dialog->canAdd());
        QPushButton* add = nullptr;
        for (QPushButton* b : dialog->findChildren<QPushButton*>())
            if (b->text() == QStringLiteral("&Add")) add = b;
        QVERIFY(add && !add->isEnabled());
        add->click(); // a disabled button does nothing
        QCOMPARE(controller.view()->plot()->store().channelCount(), std::size_t(3));

        // With the matching feedback it is allowed: command - feedback, in the command's unit.
        dialog->choose(MathOp::FollowingError, QStringLiteral("PCMD"), QStringLiteral("PFB"));
        QCOMPARE(dialog->preview(), QStringLiteral("New channel: FE(PCMD-PFB) [POS]"));
        QVERIFY(dialog->canAdd());
    }
};

QTEST_MAIN(ScopeMathTest)
#include "scope_math_test.moc"
