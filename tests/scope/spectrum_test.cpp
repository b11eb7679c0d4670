// Spectrum on sines whose answers are known in closed form: the peak of an off-bin tone under Hann within a
// bin and its amplitude within the window's scalloping loss, a bin-centred tone under the rectangular window
// exactly, DC and Nyquist scaling, resolution fs / N, and the rule for timed samples (resample jitter,
// refuse gaps).
#include "scope/real_fft.h"
#include "scope/spectrum.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <thread>
#include <vector>

using scope::computeSpectrum;
using scope::Spectrum;
using scope::SpectrumWindow;

namespace {

constexpr double kPi = std::numbers::pi;

std::vector<double> sine(double amplitude, double f_hz, double fs_hz, std::size_t n, double offset = 0,
                         double phase = 0.3) {
    std::vector<double> v(n);
    for (std::size_t i = 0; i < n; ++i)
        v[i] = offset + amplitude * std::sin(2 * kPi * f_hz * double(i) / fs_hz + phase);
    return v;
}

double db(double amplitude) {
    return 20 * std::log10(amplitude);
}

// Hann's response to a tone delta bins off a bin's centre, relative to on-centre (large N):
// sinc(delta) / (1 - delta^2).
double hannScallopDb(double delta) {
    if (delta == 0) return 0;
    return db(std::abs(std::sin(kPi * delta) / (kPi * delta) / (1 - delta * delta)));
}

} // namespace

TEST(Spectrum, HannPeakOfOffBinSineWithinOneBinAndHalfADecibel) {
    const double fs = 1000, f = 37.3, amplitude = 2.0;
    const std::size_t n = 4096;
    const Spectrum s = computeSpectrum(sine(amplitude, f, fs, n), 1 / fs, {SpectrumWindow::Hann}, "VEL");
    ASSERT_TRUE(s.ok()) << s.error;
    EXPECT_DOUBLE_EQ(s.resolution_hz, fs / double(n));
    EXPECT_DOUBLE_EQ(s.sampleRate_hz, fs);
    EXPECT_EQ(s.magnitude_db.size(), n / 2 + 1);
    EXPECT_EQ(s.dbUnit(), "dB re 1 VEL");
    ASSERT_TRUE(s.peak);
    const double exactBin = f / s.resolution_hz; // 152.78...
    EXPECT_EQ(s.peak->bin, std::size_t(std::lround(exactBin)));
    EXPECT_NEAR(s.peak->binFrequency_hz, f, s.resolution_hz);
    EXPECT_NEAR(s.peak->frequency_hz, f, 0.1 * s.resolution_hz); // interpolation lands well inside the bin
    EXPECT_NEAR(s.peak->magnitude_db, db(amplitude), 0.5);
    // The largest bin reads low by Hann's scalloping loss at its offset from the tone.
    const double delta = double(s.peak->bin) - exactBin;
    EXPECT_NEAR(s.peak->magnitude_db, db(amplitude) + hannScallopDb(delta), 0.01);
    // The parabola's vertex recovers part of that loss.
    EXPECT_LT(std::abs(s.peak->interpolated_db - db(amplitude)), std::abs(s.peak->magnitude_db - db(amplitude)));
}

TEST(Spectrum, HammingAmplitudeWithinItsScallopingLoss) {
    const double fs = 1000, f = 123.45, amplitude = 0.25;
    const Spectrum s = computeSpectrum(sine(amplitude, f, fs, 8192), 1 / fs, {SpectrumWindow::Hamming});
    ASSERT_TRUE(s.ok());
    ASSERT_TRUE(s.peak);
    EXPECT_NEAR(s.peak->frequency_hz, f, s.resolution_hz);
    EXPECT_LE(s.peak->magnitude_db, db(amplitude) + 0.01);
    EXPECT_GE(s.peak->magnitude_db, db(amplitude) - 1.75); // Hamming's worst scalloping loss
}

TEST(Spectrum, RectangularBinCentredSineIsExact) {
    // fs = N = 1024: bins are 1 Hz apart and a 100 Hz tone sits on bin 100 with no leakage at all.
    const double fs = 1024, f = 100, amplitude = 2.5, offset = 0.75;
    const std::size_t n = 1024;
    const Spectrum s = computeSpectrum(sine(amplitude, f, fs, n, offset), 1 / fs, {SpectrumWindow::Rectangular});
    ASSERT_TRUE(s.ok());
    EXPECT_DOUBLE_EQ(s.resolution_hz, 1.0);
    EXPECT_NEAR(s.magnitude_db[100], db(amplitude), 1e-9);
    EXPECT_NEAR(s.magnitude_db[0], db(offset), 1e-9); // DC: the mean, not doubled
    for (std::size_t k = 1; k < s.magnitude_db.size(); ++k) {
        if (k == 100) continue;
        EXPECT_LT(s.magnitude_db[k], db(amplitude) - 200) << "bin " << k;
    }
    ASSERT_TRUE(s.peak);
    EXPECT_EQ(s.peak->bin, 100u);
    EXPECT_DOUBLE_EQ(s.peak->frequency_hz, f); // a lone bin: no interpolation
    EXPECT_NEAR(s.peak->magnitude_db, db(amplitude), 1e-9);
    EXPECT_NEAR(s.peak->interpolated_db, db(amplitude), 1e-9);
}

TEST(Spectrum, NyquistToneReadsItsAmplitude) {
    // A (-1)^n: a cosine at fs / 2, the unpaired last bin.
    std::vector<double> v(256);
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = (i % 2 ? -3.0 : 3.0);
    const Spectrum s = computeSpectrum(v, 0.001, {SpectrumWindow::Rectangular});
    ASSERT_TRUE(s.ok());
    EXPECT_NEAR(s.magnitude_db.back(), db(3.0), 1e-9);
    ASSERT_TRUE(s.peak);
    EXPECT_DOUBLE_EQ(s.peak->frequency_hz, 500.0);
}

TEST(Spectrum, ResolutionIsSampleRateOverLength) {
    const Spectrum s = computeSpectrum(std::vector<double>(1000, 1.0), 0.002, {SpectrumWindow::Hann});
    ASSERT_TRUE(s.ok());
    EXPECT_DOUBLE_EQ(s.resolution_hz, 500.0 / 1000.0);
    EXPECT_DOUBLE_EQ(s.frequencyAt(10), 5.0);
    EXPECT_EQ(s.sampleCount, 1000u);
}

TEST(Spectrum, LargeOffsetDoesNotHideTheTonePeak) {
    // An offset 10^4 times the tone: under Hann it leaks into bin 1, which the peak search skips.
    const double fs = 1000, f = 50;
    const Spectrum s = computeSpectrum(sine(0.1, f, fs, 2000, 1000.0), 1 / fs, {SpectrumWindow::Hann});
    ASSERT_TRUE(s.ok());
    ASSERT_TRUE(s.peak);
    EXPECT_NEAR(s.peak->frequency_hz, f, s.resolution_hz);
    EXPECT_NEAR(s.magnitude_db[0], db(1000.0), 1e-6);
}

// A loud low tone and a quiet high one: the plain peak is the low one, the peak searched from a frequency
// between them is the high one, refined like the plain peak; past Nyquist there is none.
TEST(Spectrum, PeakFromAFrequencySkipsWhatLiesBelowIt) {
    const double fs = 1000;
    std::vector<double> v = sine(1.0, 12.3, fs, 2000);
    const std::vector<double> high = sine(0.01, 171.7, fs, 2000);
    for (std::size_t i = 0; i < v.size(); ++i) v[i] += high[i];
    const Spectrum s = computeSpectrum(v, 1 / fs, {SpectrumWindow::Hann});
    ASSERT_TRUE(s.ok() && s.peak);
    EXPECT_NEAR(s.peak->frequency_hz, 12.3, s.resolution_hz);
    const auto above = scope::findPeakFrom(s, 50);
    ASSERT_TRUE(above);
    EXPECT_NEAR(above->frequency_hz, 171.7, 0.1 * s.resolution_hz);
    EXPECT_NEAR(above->interpolated_db, db(0.01), 0.5);
    EXPECT_EQ(scope::findPeakFrom(s, 0)->bin, s.peak->bin);
    EXPECT_FALSE(scope::findPeakFrom(s, 600));
}

// A servo's velocity step with a lightly damped mechanical mode: the step's own content is largest at low
// frequency, the resonance stands out of its surroundings; encoder-like noise rides on both.
TEST(Spectrum, ProminentPeakOfAStepIsItsResonanceNotItsLowFrequencyContent) {
    const double fs = 4000, f = 263.7;
    const std::size_t n = 4096;
    std::mt19937 random(7);
    std::uniform_real_distribution<double> noise(-1e-4, 1e-4);
    std::vector<double> v(n);
    for (std::size_t i = 0; i < n; ++i) { // the step at 0.1 s of the 1.024 s record
        const double t = double(i) / fs - 0.1;
        v[i] = noise(random) +
               (t < 0 ? 0 : 1 - std::exp(-t / 0.02) + 0.003 * std::exp(-t / 0.05) * std::sin(2 * kPi * f * t));
    }
    const Spectrum s = computeSpectrum(v, 1 / fs, {SpectrumWindow::Hann});
    ASSERT_TRUE(s.ok() && s.peak);
    EXPECT_LT(s.peak->frequency_hz, 10.0); // the largest bin is the step's
    const auto prominent = scope::findProminentPeak(s);
    ASSERT_TRUE(prominent);
    EXPECT_NEAR(prominent->frequency_hz, f, s.resolution_hz);
}

TEST(Spectrum, ProminentPeakOfNoiseAloneIsTheLargestBin) {
    std::mt19937 random(11);
    std::normal_distribution<double> noise(0, 1);
    std::vector<double> v(4096);
    for (double& x : v) x = noise(random);
    const Spectrum s = computeSpectrum(v, 1e-3, {SpectrumWindow::Hann});
    ASSERT_TRUE(s.ok() && s.peak);
    EXPECT_EQ(scope::findProminentPeak(s)->bin, s.peak->bin);
    EXPECT_FALSE(scope::findProminentPeak(computeSpectrum(std::vector<double>{1, 2}, 1e-3)));
}

TEST(Spectrum, RefusesWhatHasNoSpectrum) {
    EXPECT_EQ(computeSpectrum(std::vector<double>{1, 2, 3}, 0.001).status, Spectrum::Status::TooShort);
    EXPECT_EQ(computeSpectrum(std::vector<double>(8, 1.0), 0).status, Spectrum::Status::BadInterval);
    std::vector<double> v(8, 1.0);
    v[5] = std::nan("");
    const Spectrum s = computeSpectrum(v, 0.001);
    EXPECT_EQ(s.status, Spectrum::Status::NotFinite);
    EXPECT_NE(s.error.find("sample 5"), std::string::npos) << s.error;
    scope::Capture c;
    EXPECT_EQ(computeSpectrum(c, 0).status, Spectrum::Status::TooShort);
}

TEST(Spectrum, CaptureChannelCarriesItsUnit) {
    scope::Capture c;
    c.interval_s = 0.0005;
    c.channels.push_back({"VFB", "VEL", sine(10, 100, 2000, 2000)});
    const Spectrum s = computeSpectrum(c, 0);
    ASSERT_TRUE(s.ok());
    EXPECT_EQ(s.unit, "VEL");
    EXPECT_DOUBLE_EQ(s.resolution_hz, 1.0);
    ASSERT_TRUE(s.peak);
    EXPECT_NEAR(s.peak->magnitude_db, 20.0, 1e-6); // bin-centred: 20 log10(10) under Hann too
}

TEST(Spectrum, EvenlyTimedStoreSamplesMatchTheCaptureSpectrum) {
    const double fs = 1000;
    const auto v = sine(1.0, 37.3, fs, 1024);
    scope::Channel ch{"VFB", "rpm", {}};
    for (std::size_t i = 0; i < v.size(); ++i) ch.samples.push_back({5.0 + double(i) / fs, v[i]});
    const Spectrum timed = computeSpectrum(ch);
    const Spectrum plain = computeSpectrum(v, 1 / fs);
    ASSERT_TRUE(timed.ok()) << timed.error;
    EXPECT_FALSE(timed.resampled);
    EXPECT_NEAR(timed.resolution_hz, plain.resolution_hz, 1e-9);
    ASSERT_EQ(timed.magnitude_db.size(), plain.magnitude_db.size());
    ASSERT_TRUE(timed.peak && plain.peak);
    EXPECT_EQ(timed.peak->bin, plain.peak->bin);
    EXPECT_NEAR(timed.peak->magnitude_db, plain.peak->magnitude_db, 1e-6);
}

TEST(Spectrum, JitteredStoreSamplesAreResampled) {
    // A slow tone polled about every 10 ms with +-2 ms jitter (fixed seed): resampled, the peak stays.
    std::mt19937 random(42);
    std::uniform_real_distribution<double> jitter(-0.002, 0.002);
    const double f = 3.0, amplitude = 5.0;
    scope::Channel ch{"PFB", "POS", {}};
    for (int i = 0; i < 2000; ++i) {
        const double t = 0.01 * i + (i == 0 || i == 1999 ? 0.0 : jitter(random));
        ch.samples.push_back({t, amplitude * std::sin(2 * kPi * f * t)});
    }
    const Spectrum s = computeSpectrum(ch);
    ASSERT_TRUE(s.ok()) << s.error;
    EXPECT_TRUE(s.resampled);
    EXPECT_NEAR(s.sampleRate_hz, 100.0, 0.1);
    ASSERT_TRUE(s.peak);
    EXPECT_NEAR(s.peak->frequency_hz, f, s.resolution_hz);
    EXPECT_NEAR(s.peak->magnitude_db, db(amplitude), 1.5); // Hann's scalloping plus interpolation error
}

TEST(Spectrum, GapInStoreSamplesIsRefusedSayingWhere) {
    scope::Channel ch{"VFB", "rpm", {}};
    for (int i = 0; i < 100; ++i) ch.samples.push_back({0.01 * i + (i >= 50 ? 0.5 : 0.0), 1.0});
    const Spectrum s = computeSpectrum(ch);
    EXPECT_EQ(s.status, Spectrum::Status::Uneven);
    EXPECT_NE(s.error.find("gap"), std::string::npos) << s.error;
    EXPECT_NE(s.error.find("t = 0.49"), std::string::npos) << s.error;
    EXPECT_TRUE(s.magnitude_db.empty());

    scope::Channel twice{"VFB", "rpm", {{0, 1}, {0.01, 1}, {0.01, 2}, {0.02, 1}, {0.03, 1}}};
    EXPECT_EQ(computeSpectrum(twice).status, Spectrum::Status::Uneven);
}

TEST(Spectrum, ConcurrentSpectraAgree) {
    // FFTW's planner is not thread-safe: spectra from several threads at once (each planning its own length)
    // must all find their own tone.
    std::vector<int> found(4, 0);
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t) {
        threads.emplace_back([t, &found] {
            const std::size_t n = 1000 + 24 * std::size_t(t); // lengths FFTW plans differently
            const double fs = double(n), f = 50.0 + 10 * t;   // 1 Hz bins: the tone is on bin f
            for (int round = 0; round < 25; ++round) {
                const Spectrum s = computeSpectrum(sine(1.0, f, fs, n), 1 / fs, {SpectrumWindow::Hann});
                if (s.ok() && s.peak && s.peak->bin == std::size_t(f) && std::abs(s.peak->magnitude_db) < 1e-6)
                    ++found[std::size_t(t)];
            }
        });
    }
    for (std::thread& th : threads) th.join();
    for (int t = 0; t < 4; ++t) EXPECT_EQ(found[std::size_t(t)], 25) << "thread " << t;
}

TEST(RealFft, TransformsAnImpulseAndOutlivesEvictionOfItsPlan) {
    // The DFT of a unit impulse at sample 1 is e^{-2 pi i k / n}. More lengths than the plan cache holds are
    // made while the first transform is alive; its plan must survive eviction.
    scope::RealFft first(64);
    ASSERT_TRUE(first.valid());
    for (std::size_t n = 65; n < 65 + 2 * scope::RealFft::kCachedPlans; ++n) {
        scope::RealFft other(n);
        ASSERT_TRUE(other.valid());
    }
    for (int round = 0; round < 2; ++round) {
        std::fill(first.input(), first.input() + 64, 0.0);
        first.input()[1] = 1;
        first.execute();
        for (std::size_t k = 0; k <= 32; ++k) {
            const double angle = -2 * kPi * double(k) / 64;
            ASSERT_NEAR(first.output()[k].real(), std::cos(angle), 1e-12) << k;
            ASSERT_NEAR(first.output()[k].imag(), std::sin(angle), 1e-12) << k;
        }
    }
    EXPECT_FALSE(scope::RealFft(0).valid());
}
