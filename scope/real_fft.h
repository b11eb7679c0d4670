// RealFft: FFTW3's real-to-complex transform of one length, with its own SIMD-aligned buffers. Plans are
// made with FFTW_ESTIMATE and kept in a small process-wide cache (the last kCachedPlans lengths), so a
// spectrum recomputed at the same length (a live trace) does not plan again.
// Threading: any thread. FFTW's planner, plan destruction and allocator are not thread-safe; they run
// behind one mutex in real_fft.cpp. execute() uses FFTW's new-array execute, which may run concurrently,
// also on a plan shared with another thread.
#pragma once

#include <complex>
#include <cstddef>
#include <memory>

namespace scope {

class RealFft {
public:
    static constexpr std::size_t kCachedPlans = 4;

    // n samples (at most INT_MAX); valid() is false if FFTW could not allocate or plan.
    explicit RealFft(std::size_t n);
    ~RealFft();
    RealFft(const RealFft&) = delete;
    RealFft& operator=(const RealFft&) = delete;

    bool valid() const { return m_plan != nullptr; }
    std::size_t size() const { return m_n; }
    double* input() { return m_in; }                             // n samples, written before execute()
    const std::complex<double>* output() const { return m_out; } // bins 0 .. n/2 after execute()
    void execute();

private:
    std::size_t m_n;
    double* m_in = nullptr;
    std::complex<double>* m_out = nullptr; // fftw_complex is layout-compatible with std::complex<double>
    std::shared_ptr<void> m_plan;          // an fftw_plan, destroyed under the lock when its last user goes
};

} // namespace scope
