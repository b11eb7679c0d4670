// ScopePlot with 1,000,000 points loaded from a .CSV on disk (written first by this bench to a temporary
// folder, then read back through the project's CSV reader as File > Open does): time to write, read and show
// it, and the frame time of a pan and of a zoom (replot with immediate refresh), printed; then the same frames
// with 8 channels of 1,000,000 points each (the scale issue: "frame, 8 x 1000000 points, ..." and "csv load,
// 1000000 points: ..." are the lines to compare between runs). Goal: a frame under 16 ms, a load under 100 ms.
// No assertions on time.
#include "scope/capture_csv.h"
#include "scope/scope_plot.h"
#include "scope/spectrum.h"

#include <qcustomplot.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

namespace {

scope::Capture bigCapture(std::size_t points) {
    scope::Capture c;
    c.interval_s = 0.001;
    c.title = "1M points";
    scope::CaptureChannel vfb{"VFB", "VEL", {}};
    vfb.values.reserve(points);
    for (std::size_t i = 0; i < points; ++i) {
        const double t = double(i) * c.interval_s;
        vfb.values.push_back(1000 * std::sin(2 * std::numbers::pi * 0.5 * t) +
                             30 * std::sin(2 * std::numbers::pi * 37 * t));
    }
    c.channels.push_back(std::move(vfb));
    return c;
}

struct Figures {
    double median_ms = 0; // wall clock
    double worst_ms = 0;
    double cpu_median_ms = 0; // this thread's CPU time: what the frame costs when the machine is shared
};

double threadCpuMs() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) / 1e6;
}

template <typename Step> Figures frames(scope::ScopePlot& plot, int count, Step step) {
    std::vector<double> ms, cpu;
    QElapsedTimer timer;
    for (int i = 0; i < count; ++i) {
        step(i);
        const double cpuStart = threadCpuMs();
        timer.start();
        plot.customPlot()->replot(QCustomPlot::rpImmediateRefresh);
        ms.push_back(double(timer.nsecsElapsed()) / 1e6);
        cpu.push_back(threadCpuMs() - cpuStart);
    }
    std::sort(ms.begin(), ms.end());
    std::sort(cpu.begin(), cpu.end());
    return {ms[ms.size() / 2], ms.back(), cpu[cpu.size() / 2]};
}

// The spectrum of 1,048,576 points (Hann window, FFT, magnitude in dB and peak): median of 5 runs (the first
// also plans the FFT; the others reuse the cached plan, as a live spectrum recomputed at one length does).
void printFftBench() {
    constexpr std::size_t kFftPoints = 1'048'576;
    std::vector<double> values(kFftPoints);
    for (std::size_t i = 0; i < kFftPoints; ++i)
        values[i] = 1000 * std::sin(2 * std::numbers::pi * 0.5 * double(i) * 0.001) +
                    30 * std::sin(2 * std::numbers::pi * 37 * double(i) * 0.001);
    std::vector<double> ms;
    for (int run = 0; run < 5; ++run) {
        QElapsedTimer timer;
        timer.start();
        const scope::Spectrum s = scope::computeSpectrum(values, 0.001, {scope::SpectrumWindow::Hann}, "VEL");
        ms.push_back(double(timer.nsecsElapsed()) / 1e6);
        if (!s.ok()) std::fprintf(stderr, "fft: %s\n", s.error.c_str());
    }
    std::sort(ms.begin(), ms.end());
    std::printf("fft, %zu points: %.1f ms\n", kFftPoints, ms[ms.size() / 2]);
}

// 8 channels of `points` samples at 1 ms, each its own mix of sines and noise so no two graphs coincide.
scope::Capture eightChannelCapture(std::size_t points) {
    scope::Capture c;
    c.interval_s = 0.001;
    c.title = "8 x 1M points";
    std::uint32_t noise = 12345; // a fixed-seed LCG: the same record every run
    for (int k = 0; k < 8; ++k) {
        scope::CaptureChannel channel{"CH" + std::to_string(k + 1), "VEL", {}};
        channel.values.reserve(points);
        for (std::size_t i = 0; i < points; ++i) {
            const double t = double(i) * c.interval_s;
            noise = noise * 1664525u + 1013904223u;
            channel.values.push_back(1000 * std::sin(2 * std::numbers::pi * (0.2 + 0.1 * k) * t) +
                                     (30 + 10 * k) * std::sin(2 * std::numbers::pi * (37 + 5 * k) * t) +
                                     double(noise >> 24) / 16.0);
        }
        c.channels.push_back(std::move(channel));
    }
    return c;
}

// Frames of a 1280x720 plot showing 8 x `points`: the whole record redrawn, panned, and zoomed in 30 steps to
// 0.85^30 of it (about 7,600 samples visible) and out again.
void printEightChannelBench(std::size_t points) {
    const scope::Capture capture = eightChannelCapture(points);
    scope::ScopePlot plot;
    plot.resize(1280, 720);
    plot.show();
    QApplication::processEvents();
    QElapsedTimer timer;
    timer.start();
    plot.showCapture(capture);
    plot.customPlot()->replot(QCustomPlot::rpImmediateRefresh);
    const double showMs = double(timer.nsecsElapsed()) / 1e6;
    const int drawn = plot.drawnPointCount(0);
    QCPAxis* x = plot.customPlot()->xAxis;
    const Figures whole = frames(plot, 30, [](int) {});
    const Figures pan = frames(plot, 60, [x](int i) { x->moveRange((i % 2 ? -1 : 1) * x->range().size() * 0.05); });
    plot.autoScale();
    const Figures zoom = frames(plot, 60, [x](int i) { x->scaleRange(i < 30 ? 0.85 : 1 / 0.85, x->range().center()); });
    std::printf("  8 channels x %zu points: show capture %.1f ms; %d points a graph drawn for the whole record\n",
                points, showMs, drawn);
    const auto print = [points](const char* what, const Figures& f) {
        std::printf("frame, 8 x %zu points, %s: median %.2f ms\n", points, what, f.median_ms);
        std::printf("  (CPU median %.2f ms, worst %.2f ms; goal < 16 ms)\n", f.cpu_median_ms, f.worst_ms);
    };
    print("whole record", whole);
    print("pan", pan);
    print("zoom in/out", zoom);
}

} // namespace

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    constexpr std::size_t kPoints = 1'000'000;
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("1m-points.csv"));
    QElapsedTimer timer;
    timer.start();
    {
        QFile out(path);
        const std::string text = scope::writeCsv(bigCapture(kPoints));
        if (!out.open(QIODevice::WriteOnly) || out.write(text.data(), qint64(text.size())) != qint64(text.size())) {
            std::fprintf(stderr, "cannot write %s\n", qPrintable(path));
            return 1;
        }
    }
    const double writeMs = double(timer.nsecsElapsed()) / 1e6;
    // File > Open's work: the file mapped in one go and parsed where it lies (no copy into a std::string);
    // then the same with QFile::readAll instead of the mapping, for comparison.
    const double readCpuStart = threadCpuMs();
    timer.start();
    QFile in(path);
    if (!in.open(QIODevice::ReadOnly)) return 1;
    const qint64 fileBytes = in.size();
    const uchar* mapped = in.map(0, fileBytes);
    if (!mapped) return 1;
    const scope::CsvReadResult read =
        scope::readCsv(std::string_view(reinterpret_cast<const char*>(mapped), std::size_t(fileBytes)));
    const double readMs = double(timer.nsecsElapsed()) / 1e6;
    const double readCpuMs = threadCpuMs() - readCpuStart;
    timer.start();
    {
        QFile again(path);
        const QByteArray bytes = again.open(QIODevice::ReadOnly) ? again.readAll() : QByteArray();
        (void)scope::readCsv(std::string_view(bytes.constData(), std::size_t(bytes.size())));
    }
    const double readAllMs = double(timer.nsecsElapsed()) / 1e6;
    if (!read.capture || read.capture->sampleCount() != kPoints) {
        std::fprintf(stderr, "reading %s: %s\n", qPrintable(path), read.error.c_str());
        return 1;
    }
    const scope::Capture& capture = *read.capture;
    scope::ScopePlot plot;
    plot.resize(1280, 720);
    plot.show();
    QApplication::processEvents();

    timer.start();
    plot.showCapture(capture);
    plot.customPlot()->replot(QCustomPlot::rpImmediateRefresh);
    const double showMs = double(timer.nsecsElapsed()) / 1e6;

    QCPAxis* x = plot.customPlot()->xAxis;
    const Figures whole = frames(plot, 30, [](int) {});
    const Figures pan = frames(plot, 60, [x](int i) { x->moveRange((i % 2 ? -1 : 1) * x->range().size() * 0.05); });
    x->setRange(400, 500); // zoomed in: 100,000 points visible
    const Figures panZoomed = frames(plot, 60, [x](int i) { x->moveRange((i % 2 ? -1 : 1) * 2.0); });
    plot.autoScale();
    const Figures zoom = frames(plot, 60, [x](int i) { x->scaleRange(i < 30 ? 0.85 : 1 / 0.85, x->range().center()); });

    std::printf("scope_plot_bench: %zu points, 1280x720 plot\n", kPoints);
    std::printf("  .CSV on disk: %.1f MB, generated and written in %.0f ms\n", double(fileBytes) / 1e6, writeMs);
    std::printf("csv load, %zu points: %.1f ms\n", kPoints, readMs);
    std::printf(
        "  (mapped and parsed by scope::readCsv; CPU %.1f ms; with QFile::readAll instead: %.1f ms; goal < 100 ms)\n",
        readCpuMs, readAllMs);
    std::printf("  show capture (copy into the store, first frame): %.1f ms\n", showMs);
    auto print = [](const char* what, const Figures& f) {
        std::printf("  frame, %-24s median %6.2f ms (CPU %6.2f ms), worst %6.2f ms   goal < 16 ms\n", what, f.median_ms,
                    f.cpu_median_ms, f.worst_ms);
    };
    print("whole record:", whole);
    print("pan, whole record:", pan);
    print("pan, 100 s window:", panZoomed);
    print("zoom in/out:", zoom);
    printEightChannelBench(kPoints);
    printFftBench();
    return 0;
}
