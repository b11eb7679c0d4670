// Closed forms of the S-curve shapes: acceleration g, velocity G = ∫g and position H = ∫G per shape.
#include "s_curve.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace drive_core::motion {

namespace {
constexpr double kPi = std::numbers::pi;

// The "modified" shapes: a ramp over [0, r], flat at h = 1/(1-r) up to τ = 1/2, mirrored after.
struct Ramped {
    double r;
    bool sine; // half-cosine ramp, else linear
    double h() const { return 1 / (1 - r); }
    double g(double t) const {
        if (t >= r) return h();
        return sine ? h() * (1 - std::cos(kPi * t / r)) / 2 : h() * t / r;
    }
    double G(double t) const {
        if (t >= r) return h() * (t - r / 2);
        return sine ? h() / 2 * (t - r / kPi * std::sin(kPi * t / r)) : h() * t * t / (2 * r);
    }
    double H(double t) const {
        if (t >= r) return rampH(r) + h() * (t - r) * t / 2;
        return rampH(t);
    }
    double rampH(double t) const { // H on [0, r]
        const double k = r / kPi;
        return sine ? h() / 2 * (t * t / 2 + k * k * (std::cos(kPi * t / r) - 1)) : h() * t * t * t / (6 * r);
    }
};

constexpr Ramped kModifiedPolynomial{0.25, false};
constexpr Ramped kModifiedSinusoid{1.0 / 3, true};

// First-half forms (τ <= 1/2); the second half follows by symmetry.
double gHalf(SCurve s, double t) {
    switch (s) {
    case SCurve::Straight: return 1;
    case SCurve::ModifiedPolynomial: return kModifiedPolynomial.g(t);
    case SCurve::Polynomial: return 6 * t * (1 - t);
    case SCurve::ModifiedSinusoid: return kModifiedSinusoid.g(t);
    case SCurve::Sinusoid: return kPi / 2 * std::sin(kPi * t);
    }
    return 1;
}
double GHalf(SCurve s, double t) {
    switch (s) {
    case SCurve::Straight: return t;
    case SCurve::ModifiedPolynomial: return kModifiedPolynomial.G(t);
    case SCurve::Polynomial: return t * t * (3 - 2 * t);
    case SCurve::ModifiedSinusoid: return kModifiedSinusoid.G(t);
    case SCurve::Sinusoid: return (1 - std::cos(kPi * t)) / 2;
    }
    return t;
}
double HHalf(SCurve s, double t) {
    switch (s) {
    case SCurve::Straight: return t * t / 2;
    case SCurve::ModifiedPolynomial: return kModifiedPolynomial.H(t);
    case SCurve::Polynomial: return t * t * t * (1 - t / 2);
    case SCurve::ModifiedSinusoid: return kModifiedSinusoid.H(t);
    case SCurve::Sinusoid: return t / 2 - std::sin(kPi * t) / (2 * kPi);
    }
    return t * t / 2;
}
} // namespace

SCurve sCurveFromLevel(int level) {
    return level >= 1 && level <= 5 ? SCurve(level) : SCurve::Straight;
}

double sCurveAcceleration(SCurve shape, double tau) {
    tau = std::clamp(tau, 0.0, 1.0);
    return gHalf(shape, tau <= 0.5 ? tau : 1 - tau);
}

double sCurveVelocity(SCurve shape, double tau) {
    tau = std::clamp(tau, 0.0, 1.0);
    if (shape == SCurve::Straight) return tau;
    return tau <= 0.5 ? GHalf(shape, tau) : 1 - GHalf(shape, 1 - tau);
}

double sCurvePosition(SCurve shape, double tau) {
    tau = std::clamp(tau, 0.0, 1.0);
    if (shape == SCurve::Straight) return tau * tau / 2;
    // H(τ) = τ - 1/2 + H(1-τ) for a shape symmetric about 1/2.
    return tau <= 0.5 ? HHalf(shape, tau) : tau - 0.5 + HHalf(shape, 1 - tau);
}

double sCurvePeak(SCurve shape) {
    return gHalf(shape, 0.5);
}

} // namespace drive_core::motion
