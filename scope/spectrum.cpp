// Spectrum: windowed real FFT (RealFft over FFTW3), single-sided amplitude in dB, peak.
#include "spectrum.h"

#include "real_fft.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <numbers>
#include <sstream>

namespace scope {

namespace {

constexpr double kFloor_db = -300;
constexpr double kFloorPower = 1e-30;         // amplitude 1e-15: the -300 dB floor
constexpr double kInterpolationRange_db = 60; // neighbours further below the peak: a lone bin
constexpr double kEvenTolerance = 1e-6;       // of the median interval: evenly spaced
constexpr double kGapFactor = 1.5;            // an interval over 1.5 x the median is a gap
constexpr double kProminence_db = 6;          // findProminentPeak: less above its surroundings is no peak
constexpr std::size_t kProminenceSmoothing = 5; // bins averaged (in power) before judging a peak

std::string seconds(double s) {
    std::ostringstream out;
    out.precision(6);
    out << s << " s";
    return out.str();
}

// Writes x * w into `in` and returns the window's sum (its coherent gain times N). The periodic window is
// symmetric about N/2 (w[N-n] = w[n]), so each cosine serves two samples. The cosines come from a rotation
// restarted from std::cos / std::sin every kExactEvery samples (rounding stays near 1e-14, at a fraction
// of the cost of a std::cos per sample).
double applyWindow(std::span<const double> x, SpectrumWindow window, double* in) {
    constexpr std::size_t kExactEvery = 256;
    const std::size_t n = x.size();
    if (window == SpectrumWindow::Rectangular) {
        std::copy(x.begin(), x.end(), in);
        return double(n);
    }
    const double a = window == SpectrumWindow::Hann ? 0.5 : 0.54;
    const double b = 1 - a;
    const double step = 2 * std::numbers::pi / double(n);
    const double cosStep = std::cos(step), sinStep = std::sin(step);
    double sum = 0, c = 1, s = 0;
    for (std::size_t i = 0; i <= n / 2; ++i) {
        if (i % kExactEvery == 0) {
            c = std::cos(step * double(i));
            s = std::sin(step * double(i));
        }
        const double w = a - b * c;
        in[i] = x[i] * w;
        sum += w;
        if (i != 0 && n - i != i) {
            in[n - i] = x[n - i] * w;
            sum += w;
        }
        const double next = c * cosStep - s * sinStep;
        s = s * cosStep + c * sinStep;
        c = next;
    }
    return sum;
}

std::size_t firstPeakBin(const Spectrum& s) {
    return s.window == SpectrumWindow::Rectangular ? 1 : 2;
}

// The peak at `bin` (> 0), refined as the header says.
SpectrumPeak peakAt(const Spectrum& s, std::size_t bin) {
    const std::size_t last = s.magnitude_db.size() - 1;
    SpectrumPeak p;
    p.bin = bin;
    p.binFrequency_hz = s.frequencyAt(p.bin);
    p.frequency_hz = p.binFrequency_hz;
    p.magnitude_db = p.interpolated_db = s.magnitude_db[bin];
    if (p.bin + 1 <= last) {
        const double alpha = s.magnitude_db[p.bin - 1], beta = p.magnitude_db, gamma = s.magnitude_db[p.bin + 1];
        if (alpha >= beta - kInterpolationRange_db && gamma >= beta - kInterpolationRange_db) {
            const double curvature = alpha - 2 * beta + gamma; // < 0: beta is the largest of the three
            const double delta = curvature < 0 ? std::clamp(0.5 * (alpha - gamma) / curvature, -0.5, 0.5) : 0.0;
            p.frequency_hz = (double(p.bin) + delta) * s.resolution_hz;
            p.interpolated_db = beta - 0.25 * (alpha - gamma) * delta;
        }
    }
    return p;
}

// The largest bin from `first` up to Nyquist; unset when first lies past Nyquist.
std::optional<SpectrumPeak> largestFrom(const Spectrum& s, std::size_t first) {
    if (s.magnitude_db.empty() || first > s.magnitude_db.size() - 1) return std::nullopt;
    const auto top = std::max_element(s.magnitude_db.begin() + std::ptrdiff_t(first), s.magnitude_db.end());
    return peakAt(s, std::size_t(top - s.magnitude_db.begin()));
}

void findPeak(Spectrum& s) {
    s.peak = largestFrom(s, firstPeakBin(s));
}

Spectrum refuse(Spectrum s, Spectrum::Status status, std::string why) {
    s.status = status;
    s.error = std::move(why);
    return s;
}

Spectrum tooShort(Spectrum s, std::size_t n) {
    return refuse(std::move(s), Spectrum::Status::TooShort,
                  std::to_string(n) + " samples: a spectrum needs at least " + std::to_string(Spectrum::kMinSamples));
}

} // namespace

Spectrum computeSpectrum(std::span<const double> values, double interval_s, const SpectrumOptions& options,
                         const std::string& unit) {
    Spectrum s;
    s.unit = unit;
    s.window = options.window;
    const std::size_t n = values.size();
    s.sampleCount = n;
    if (!std::isfinite(interval_s) || interval_s <= 0)
        return refuse(s, Spectrum::Status::BadInterval, "the sample interval must be a positive time");
    if (n < Spectrum::kMinSamples) return tooShort(s, n);
    if (n > std::size_t(INT_MAX))
        return refuse(s, Spectrum::Status::TooLong, std::to_string(n) + " samples: too many for one FFT");
    for (std::size_t i = 0; i < n; ++i)
        if (!std::isfinite(values[i]))
            return refuse(s, Spectrum::Status::NotFinite, "sample " + std::to_string(i) + " is not a finite number");
    s.sampleRate_hz = 1 / interval_s;
    s.resolution_hz = s.sampleRate_hz / double(n);

    RealFft fft(n);
    if (!fft.valid()) return refuse(s, Spectrum::Status::TooLong, "no memory for an FFT of this length");
    const double windowSum = applyWindow(values, options.window, fft.input());
    fft.execute();

    // Single-sided amplitude: 2 |X_k| / sum(w), except DC and (N even) Nyquist, which have no mirror image.
    // dB = 10 log10(amplitude^2), through the natural log (faster than log10 in glibc).
    const std::size_t bins = n / 2 + 1;
    const double twoSided = 1 / (windowSum * windowSum);
    const double oneSided = 4 * twoSided;
    const double dbPerLn = 10 / std::numbers::ln10;
    s.magnitude_db.resize(bins);
    const std::complex<double>* out = fft.output();
    for (std::size_t k = 0; k < bins; ++k) {
        const bool unpaired = k == 0 || 2 * k == n;
        const double power = std::norm(out[k]) * (unpaired ? twoSided : oneSided);
        s.magnitude_db[k] = power > kFloorPower ? dbPerLn * std::log(power) : kFloor_db;
    }
    findPeak(s);
    return s;
}

std::optional<SpectrumPeak> findPeakFrom(const Spectrum& s, double from_hz) {
    if (!s.ok() || !(s.resolution_hz > 0)) return std::nullopt;
    const double bin = std::ceil(std::max(from_hz, 0.0) / s.resolution_hz - 1e-9);
    if (bin > double(s.magnitude_db.size())) return std::nullopt;
    return largestFrom(s, std::max(firstPeakBin(s), std::size_t(bin)));
}

Spectrum computeSpectrum(const Capture& capture, std::size_t channel, const SpectrumOptions& options) {
    if (channel >= capture.channels.size()) {
        Spectrum s;
        s.window = options.window;
        return refuse(s, Spectrum::Status::TooShort, "the capture has no channel " + std::to_string(channel + 1));
    }
    const CaptureChannel& c = capture.channels[channel];
    return computeSpectrum(c.values, capture.interval_s, options, c.unit);
}

Spectrum computeSpectrum(const Channel& channel, const SpectrumOptions& options) {
    const auto& samples = channel.samples;
    Spectrum s;
    s.unit = channel.unit;
    s.window = options.window;
    s.sampleCount = samples.size();
    if (samples.size() < Spectrum::kMinSamples) return tooShort(s, samples.size());

    std::vector<double> steps(samples.size() - 1);
    for (std::size_t i = 0; i + 1 < samples.size(); ++i) {
        steps[i] = samples[i + 1].time_s - samples[i].time_s;
        if (!(steps[i] > 0))
            return refuse(s, Spectrum::Status::Uneven,
                          "the sample times do not ascend at t = " + seconds(samples[i + 1].time_s));
    }
    std::vector<double> sorted = steps;
    const auto middle = sorted.begin() + std::ptrdiff_t(sorted.size() / 2);
    std::nth_element(sorted.begin(), middle, sorted.end());
    const double median = *middle;
    bool even = true;
    for (std::size_t i = 0; i < steps.size(); ++i) {
        if (steps[i] > kGapFactor * median)
            return refuse(s, Spectrum::Status::Uneven,
                          "a gap of " + seconds(steps[i]) + " at t = " + seconds(samples[i].time_s) +
                              " (samples every " + seconds(median) +
                              "): the spectrum needs evenly spaced samples; choose a stretch without gaps");
        even = even && std::abs(steps[i] - median) <= kEvenTolerance * median;
    }

    const std::size_t n = samples.size();
    const double t0 = samples.front().time_s;
    const double interval = (samples.back().time_s - t0) / double(n - 1);
    std::vector<double> values(n);
    if (even) {
        for (std::size_t i = 0; i < n; ++i) values[i] = samples[i].value;
    } else {
        // Linear interpolation at t0 + i * interval; `j` walks the samples once.
        std::size_t j = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const double t = i + 1 == n ? samples.back().time_s : t0 + double(i) * interval;
            while (j + 2 < n && samples[j + 1].time_s <= t) ++j;
            const Sample& a = samples[j];
            const Sample& b = samples[j + 1];
            values[i] = a.value + (b.value - a.value) * std::clamp((t - a.time_s) / (b.time_s - a.time_s), 0.0, 1.0);
        }
    }
    Spectrum result = computeSpectrum(values, interval, options, channel.unit);
    result.resampled = !even;
    return result;
}

std::optional<SpectrumPeak> findProminentPeak(const Spectrum& s) {
    if (!s.ok() || s.magnitude_db.empty()) return std::nullopt;
    const std::size_t first = firstPeakBin(s), last = s.magnitude_db.size() - 1;
    constexpr std::size_t h = kProminenceSmoothing / 2;
    if (first + 2 * h + 2 > last) return largestFrom(s, first);
    // Power prefix sums in long double: a step's 1/f content spans 10^11 in power over 500,000 bins.
    std::vector<long double> prefix(s.magnitude_db.size() + 1, 0.0L);
    for (std::size_t k = 0; k <= last; ++k)
        prefix[k + 1] = prefix[k] + (k < first ? 0.0L : std::pow(10.0L, (long double)s.magnitude_db[k] / 10));
    auto meanDb = [&prefix](std::size_t from, std::size_t to) { // bins from..to, both included
        const long double mean = (prefix[to + 1] - prefix[from]) / (long double)(to + 1 - from);
        return mean > 0 ? double(10 * std::log10(mean)) : kFloor_db;
    };
    auto smoothed = [&](std::size_t k) { return meanDb(k - h, k + h); };
    std::optional<std::size_t> best;
    double bestHeight = kProminence_db;
    for (std::size_t k = first + h + 1; k + h + 1 <= last; ++k) {
        const double v = smoothed(k);
        if (v < smoothed(k - 1) || v < smoothed(k + 1)) continue; // not a local maximum
        const auto from = std::max(first, std::size_t(std::ceil(double(k) / std::numbers::sqrt2)));
        const auto to = std::min(last, std::max(k + 1, std::size_t(double(k) * std::numbers::sqrt2)));
        const double height = v - meanDb(from, to);
        if (height > bestHeight) {
            bestHeight = height;
            best = k;
        }
    }
    if (!best) return largestFrom(s, first);
    const auto around = s.magnitude_db.begin() + std::ptrdiff_t(*best - h);
    return peakAt(s, std::size_t(std::max_element(around, around + 2 * h + 1) - s.magnitude_db.begin()));
}

} // namespace scope
