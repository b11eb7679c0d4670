// RealFft: buffers from fftw_malloc, plans from a small cache, every non-execute FFTW call under one lock.
#include "real_fft.h"

#include <fftw3.h>

#include <algorithm>
#include <climits>
#include <mutex>
#include <vector>

namespace scope {

namespace {

std::mutex& fftwLock() {
    static std::mutex lock;
    return lock;
}

struct CachedPlan {
    int n = 0;
    int inAlignment = 0; // a plan may only be executed on arrays aligned as the ones it was made with
    int outAlignment = 0;
    std::shared_ptr<void> plan;
};

// Most recently used first. Guarded by fftwLock().
std::vector<CachedPlan>& planCache() {
    static std::vector<CachedPlan> cache;
    return cache;
}

// Called with the lock held: the deleter takes it again, so evicted plans are destroyed by the caller after
// it lets go.
std::shared_ptr<void> planFor(int n, double* in, fftw_complex* out, std::vector<CachedPlan>& evicted) {
    const int inAlignment = fftw_alignment_of(in);
    const int outAlignment = fftw_alignment_of(reinterpret_cast<double*>(out));
    auto& cache = planCache();
    const auto found = std::find_if(cache.begin(), cache.end(), [&](const CachedPlan& c) {
        return c.n == n && c.inAlignment == inAlignment && c.outAlignment == outAlignment;
    });
    if (found != cache.end()) {
        std::rotate(cache.begin(), found, found + 1);
        return cache.front().plan;
    }
    // FFTW_ESTIMATE neither measures nor writes the arrays.
    const fftw_plan plan = fftw_plan_dft_r2c_1d(n, in, out, FFTW_ESTIMATE);
    if (!plan) return nullptr;
    std::shared_ptr<void> shared(plan, [](void* p) {
        const std::lock_guard guard(fftwLock());
        fftw_destroy_plan(static_cast<fftw_plan>(p));
    });
    cache.insert(cache.begin(), {n, inAlignment, outAlignment, shared});
    while (cache.size() > RealFft::kCachedPlans) {
        evicted.push_back(std::move(cache.back()));
        cache.pop_back();
    }
    return shared;
}

} // namespace

RealFft::RealFft(std::size_t n) : m_n(n) {
    if (n == 0 || n > std::size_t(INT_MAX)) return;
    std::vector<CachedPlan> evicted; // destroyed after the guard below lets go
    const std::lock_guard guard(fftwLock());
    m_in = fftw_alloc_real(n);
    m_out = reinterpret_cast<std::complex<double>*>(fftw_alloc_complex(n / 2 + 1));
    if (m_in && m_out) m_plan = planFor(int(n), m_in, reinterpret_cast<fftw_complex*>(m_out), evicted);
}

RealFft::~RealFft() {
    m_plan.reset(); // takes the lock itself if this was the plan's last user
    const std::lock_guard guard(fftwLock());
    fftw_free(m_out);
    fftw_free(m_in);
}

void RealFft::execute() {
    fftw_execute_dft_r2c(static_cast<fftw_plan>(m_plan.get()), m_in, reinterpret_cast<fftw_complex*>(m_out));
}

} // namespace scope
