// Spectrum (FFT, by FFTW3) of one channel, widget-free: window, magnitude in dB, frequency resolution and
// the largest peak. Decisions, so that every reading means one thing:
// - Magnitude is the single-sided amplitude spectrum in dB re 1 channel unit ("dB re 1 VEL"), corrected for
//   the window's coherent gain (sum of the window): a sine of amplitude A centred on a bin reads
//   20 log10(A) under any window; the DC bin reads 20 log10|mean|. Off-centre tones read lower by the
//   window's scalloping loss (at most 3.92 dB rectangular, 1.42 dB Hann, 1.75 dB Hamming). Floor -300 dB.
// - Windows are the periodic (DFT-even) forms over all N samples; no zero padding: bin k is k fs / N and
//   the resolution is fs / N.
// - The peak is the largest bin from the first bin outside DC's main lobe (bin 1 rectangular, bin 2 Hann
//   and Hamming) up to Nyquist, so an offset never reads as a peak. Its frequency and height are refined
//   by a parabola through the dB values of the bin and its two neighbours (Smith's QIFFT), when both
//   neighbours lie within 60 dB of it; otherwise (a lone bin: a bin-centred tone, rectangular window) the
//   bin's own centre and value are reported.
// - Samples at their own times (a store's live trace): evenly spaced (within 1e-6 of the median interval)
//   are used as they are; jittered ones (every interval within 1.5 x the median) are linearly resampled
//   onto N even points from the first time to the last (resampled = true); a gap (an interval over 1.5 x
//   the median) or times that do not ascend are refused with an error that says where.
// Threading: any thread (FFTW is reached through RealFft, which keeps its planner behind a mutex).
#pragma once

#include "capture.h"
#include "series_store.h"

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace scope {

enum class SpectrumWindow { Rectangular, Hann, Hamming };

struct SpectrumOptions {
    SpectrumWindow window = SpectrumWindow::Hann;
};

struct SpectrumPeak {
    std::size_t bin = 0;
    double binFrequency_hz = 0; // bin * resolution_hz
    double frequency_hz = 0;    // interpolated between bins (see above); = binFrequency_hz for a lone bin
    double magnitude_db = 0;    // the largest bin's own value
    double interpolated_db = 0; // the parabola's vertex: closer to the tone's amplitude off bin centre
};

struct Spectrum {
    enum class Status {
        Ok,
        TooShort,    // fewer than kMinSamples samples
        TooLong,     // more samples than FFTW's int length holds
        BadInterval, // interval not positive and finite
        NotFinite,   // a sample is NaN or infinite
        Uneven,      // timed samples with a gap, or times that do not ascend
    };
    static constexpr std::size_t kMinSamples = 4;

    Status status = Status::Ok;
    std::string error; // why there is no spectrum, in words; empty when Ok
    std::string unit;  // the channel's unit: magnitudes are dB re 1 of it
    SpectrumWindow window = SpectrumWindow::Hann;
    std::size_t sampleCount = 0;      // N
    double sampleRate_hz = 0;         // fs
    double resolution_hz = 0;         // fs / N, the spacing of the bins
    bool resampled = false;           // timed samples were resampled onto even times first
    std::vector<double> magnitude_db; // bins 0 .. N/2; bin k is at k * resolution_hz
    std::optional<SpectrumPeak> peak; // unset when no bin lies outside DC's main lobe

    bool ok() const { return status == Status::Ok; }
    double frequencyAt(std::size_t bin) const { return double(bin) * resolution_hz; }
    std::string dbUnit() const { return unit.empty() ? "dB" : "dB re 1 " + unit; }
};

// values sampled every interval_s; unit only labels the result.
Spectrum computeSpectrum(std::span<const double> values, double interval_s, const SpectrumOptions& options = {},
                         const std::string& unit = {});
// One channel of a capture (out of range: TooShort with an error naming it).
Spectrum computeSpectrum(const Capture& capture, std::size_t channel, const SpectrumOptions& options = {});
// A store's channel, at its samples' own times (see the resampling rule above).
Spectrum computeSpectrum(const Channel& channel, const SpectrumOptions& options = {});
// The peak as above, searched only from the first bin at or above from_hz (and outside DC's main lobe): a
// resonance above a loop's bandwidth, where a step's own 1/f content would otherwise be the largest. Unset
// when the spectrum is not Ok or from_hz lies past Nyquist.
std::optional<SpectrumPeak> findPeakFrom(const Spectrum& spectrum, double from_hz);
// The peak that stands highest above its surroundings (the spectrum view's default): on the spectrum averaged
// over 5 bins (in power), the local maximum outside DC's main lobe that stands furthest above the mean power
// of the bins within half an octave either side of it; reported at the largest bin of its 5. A resonance
// stands out; a step's 1/f content falls steadily and stands above nothing; the average of 5 noise bins
// seldom stands 6 dB above its neighbourhood. When nothing stands 6 dB or more above its surroundings, the
// largest peak (as Spectrum::peak). Unset when the spectrum is not Ok. Linear in the number of bins.
std::optional<SpectrumPeak> findProminentPeak(const Spectrum& spectrum);

} // namespace scope
