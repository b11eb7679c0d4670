// Frequency response estimate: differenced, detrended, tail-tapered FFTs, smoothed H1 estimator.
#include "frequency_response.h"

#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

namespace scope {

namespace {
using Complex = std::complex<double>;
constexpr double kMinDb = -3.0;
constexpr double kTaperFraction = 0.1;    // of the record, at its end
constexpr double kUnityToleranceDb = 1.5; // low-frequency gain this close to 0 dB: a unity-feedback loop
constexpr std::size_t kMinSamples = 16;

double toDb(double magnitude) {
    return 20 * std::log10(std::max(magnitude, 1e-12));
}
double toDeg(double radians) {
    return radians * 180 / std::numbers::pi;
}

// Least-squares line a + b i through the samples.
std::pair<double, double> lineThrough(const std::vector<double>& d) {
    const double n = double(d.size());
    double sy = 0, siy = 0;
    for (std::size_t i = 0; i < d.size(); ++i) {
        sy += d[i];
        siy += double(i) * d[i];
    }
    const double si = n * (n - 1) / 2, sii = (n - 1) * n * (2 * n - 1) / 6;
    const double b = (n * siy - si * sy) / (n * sii - si * si);
    return {(sy - b * si) / n, b};
}

// First differences less their mean (or the samples less their line), the last tenth tapered with a half
// Hann window.
std::vector<double> prepare(const std::vector<double>& x, bool difference) {
    std::vector<double> d = x;
    if (difference) {
        d.pop_back();
        for (std::size_t i = 0; i + 1 < x.size(); ++i) d[i] = x[i + 1] - x[i];
    }
    auto [a, b] = lineThrough(d);
    if (difference) {
        a = 0;
        for (const double v : d) a += v / double(d.size());
        b = 0;
    }
    const std::size_t taper = std::max<std::size_t>(1, std::size_t(kTaperFraction * double(d.size())));
    for (std::size_t i = 0; i < d.size(); ++i) {
        d[i] -= a + b * double(i);
        const std::size_t fromEnd = d.size() - 1 - i;
        if (fromEnd < taper) d[i] *= 0.5 - 0.5 * std::cos(std::numbers::pi * double(fromEnd) / double(taper));
    }
    return d;
}

// log-frequency interpolation of where y crosses level between (f0, y0) and (f1, y1).
double crossAt(double f0, double y0, double f1, double y1, double level) {
    const double t = y1 == y0 ? 0 : (level - y0) / (y1 - y0);
    return std::exp(std::log(f0) + t * (std::log(f1) - std::log(f0)));
}

void findMargin(FrequencyResponse& r, const std::vector<double>& freqs, const std::vector<Complex>& h) {
    if (std::abs(r.reference_db) > kUnityToleranceDb) {
        r.marginNote = "no phase margin: the low-frequency gain is not 0 dB, so the record is not a "
                       "unity-feedback closed loop whose open loop could be estimated";
        return;
    }
    // L = H / (1 - H) for unity feedback; the crossover is the first fall of |L| through 1.
    double previousMag = 0, previousF = 0;
    for (std::size_t i = 0; i < h.size(); ++i) {
        const Complex l = h[i] / (Complex(1) - h[i]);
        const double mag = std::abs(l);
        if (i > 0 && previousMag > 1 && mag <= 1) {
            r.crossover_hz = crossAt(previousF, toDb(previousMag), freqs[i], toDb(mag), 0);
            r.phaseMargin_deg = 180 + toDeg(std::arg(l));
            return;
        }
        previousMag = mag;
        previousF = freqs[i];
    }
    r.marginNote = "no phase margin: the estimated open loop H/(1-H) does not cross 0 dB within the data";
}
} // namespace

FrequencyResponse estimateFrequencyResponse(const std::vector<double>& input, const std::vector<double>& output,
                                            double interval_s, const FrequencyResponseOptions& options) {
    FrequencyResponse r;
    if (input.size() != output.size() || input.size() < kMinSamples || !(interval_s > 0)) {
        r.status = FrequencyResponse::Status::TooShort;
        r.error = "needs at least 16 samples of input and output taken together";
        return r;
    }
    Eigen::FFT<double> fft;
    std::vector<Complex> x, y;
    fft.fwd(x, prepare(input, options.difference));
    fft.fwd(y, prepare(output, options.difference));
    const std::size_t n = x.size();
    const std::size_t last = n / 2; // bins 1 .. n/2 - 1: no DC (removed), no Nyquist
    double peak = 0;
    for (std::size_t k = 1; k < last; ++k) peak = std::max(peak, std::abs(x[k]));
    std::vector<double> freqs;
    std::vector<Complex> h;
    const int m = std::max(0, options.smoothBins);
    for (std::size_t k = 1; k < last && peak > 0; ++k) {
        if (std::abs(x[k]) < options.minInputFraction * peak) continue;
        Complex sxy = 0;
        double sxx = 0;
        for (int j = -m; j <= m; ++j) {
            const std::ptrdiff_t b = std::ptrdiff_t(k) + j;
            if (b < 1 || b >= std::ptrdiff_t(last)) continue;
            sxy += y[std::size_t(b)] * std::conj(x[std::size_t(b)]);
            sxx += std::norm(x[std::size_t(b)]);
        }
        freqs.push_back(double(k) / (double(n) * interval_s));
        h.push_back(sxy / sxx);
    }
    if (h.size() < 3) {
        r.status = FrequencyResponse::Status::NoExcitation;
        r.error = "the input does not change enough (a step or chirp of the command is needed)";
        return r;
    }

    double unwrapped = 0;
    for (std::size_t i = 0; i < h.size(); ++i) {
        const double deg = toDeg(std::arg(h[i]));
        unwrapped = i == 0 ? deg : unwrapped + std::remainder(deg - unwrapped, 360.0);
        r.points.push_back({freqs[i], toDb(std::abs(h[i])), unwrapped});
    }
    const std::size_t refCount = std::clamp<std::size_t>(std::size_t(options.referenceBins), 1, h.size());
    double reference = 0;
    for (std::size_t i = 0; i < refCount; ++i) reference += std::abs(h[i]) / double(refCount);
    r.reference_db = toDb(reference);

    const double level = r.reference_db + kMinDb;
    for (std::size_t i = 1; i < r.points.size(); ++i) {
        const FrequencyPoint& a = r.points[i - 1];
        const FrequencyPoint& b = r.points[i];
        if (a.magnitude_db >= level && b.magnitude_db < level) {
            r.bandwidth_hz = crossAt(a.frequency_hz, a.magnitude_db, b.frequency_hz, b.magnitude_db, level);
            const double t = std::log(*r.bandwidth_hz / a.frequency_hz) / std::log(b.frequency_hz / a.frequency_hz);
            r.phaseAtBandwidth_deg = a.phase_deg + t * (b.phase_deg - a.phase_deg);
            break;
        }
    }
    if (!r.bandwidth_hz)
        r.bandwidthNote = "the gain stays within 3 dB of its low-frequency value up to the last usable bin";
    findMargin(r, freqs, h);
    return r;
}

} // namespace scope
