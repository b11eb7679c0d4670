// Frequency response (Bode) of a recorded input/output pair, e.g. VCMD -> VFB of a velocity step: H(f) from
// Eigen's FFT, the -3 dB bandwidth and, for a unity-feedback closed loop, the phase margin of the loop it
// implies. Widget-free value functions; the Bode view plots the result.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace scope {

struct FrequencyResponseOptions {
    // Bins whose input spectrum is below this fraction of its largest bin are dropped: there the ratio is
    // mostly noise (and at the zeros of a step-and-back input it is undefined).
    double minInputFraction = 0.1;
    // Cross and auto spectra are averaged over +-smoothBins neighbours before dividing (fewer wiggles from
    // the feedback's quantisation; the frequency resolution stays 1 / record length).
    int smoothBins = 1;
    // The low-frequency gain is the mean magnitude of this many lowest kept bins.
    int referenceBins = 3;
    // Difference both signals first: right for a step (it becomes an impulse, flat in frequency); wrong for a
    // chirp, whose difference grows with frequency and starves the low bins. Off: a straight line is
    // removed instead.
    bool difference = true;
};

struct FrequencyPoint {
    double frequency_hz = 0;
    double magnitude_db = 0; // 20 log10 |H|
    double phase_deg = 0;    // unwrapped from the lowest kept bin, starting within +-180
};

struct FrequencyResponse {
    enum class Status { Ok, TooShort, NoExcitation };
    Status status = Status::Ok;
    std::string error; // why there is no result, in words
    std::vector<FrequencyPoint> points;

    double reference_db = 0; // low-frequency gain the bandwidth is measured against
    // First frequency where the gain falls 3 dB below reference_db, interpolated in log f between bins.
    std::optional<double> bandwidth_hz;
    std::optional<double> phaseAtBandwidth_deg;
    std::string bandwidthNote; // why there is no bandwidth: the gain never falls 3 dB within the data
    // The measurement is a closed loop (VFB follows VCMD): the open loop is estimated as L = H / (1 - H),
    // which holds for unity feedback, and the margin is 180 + angle L where |L| crosses 0 dB. nullopt with
    // marginNote saying why (the gain is not ~0 dB at low frequency, or |L| does not cross 1 in the data).
    std::optional<double> phaseMargin_deg;
    std::optional<double> crossover_hz;
    std::string marginNote;
};

// input and output sampled together every interval_s. Both are first-differenced (a step becomes an
// impulse, whose spectrum is flat; H is unchanged because the same linear operation applies to both) and
// their mean removed (detrend) -- or, with difference off, their least-squares line removed -- then the
// last 10 % tapered (a half-Hann window that spares a step at the start of the record), then
// H = <Y conj X> / <|X|^2>.
FrequencyResponse estimateFrequencyResponse(const std::vector<double>& input, const std::vector<double>& output,
                                            double interval_s, const FrequencyResponseOptions& options = {});

} // namespace scope
