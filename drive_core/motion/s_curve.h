// Acceleration shapes for profile segments (BDS5 SCRV 1-5, Table 3.7): the segment's acceleration rate is
// the *average* (L2293), so each shape is a normalised curve g(τ) on τ = t/T in [0, 1] with ∫g = 1.
// All shapes are symmetric about τ = 1/2, so a segment's duration and distance do not depend on the shape.
#pragma once

namespace drive_core::motion {

// The manual names the five levels but their curves are in app note B101, which we do not have. Chosen
// (documented in docs, peak = the highest acceleration as a multiple of the average):
//   Straight           g = 1                                                    peak 1
//   ModifiedPolynomial linear ramps over the first and last 25 %, flat between  peak 4/3
//   Polynomial         g = 6τ(1-τ)                                              peak 3/2
//   ModifiedSinusoid   half-cosine ramps over the first and last third, flat    peak 3/2
//   Sinusoid           g = (π/2)·sin(πτ)                                        peak π/2
enum class SCurve { Straight = 1, ModifiedPolynomial = 2, Polynomial = 3, ModifiedSinusoid = 4, Sinusoid = 5 };

// SCRV 1-5 to the shape; anything else is Straight.
SCurve sCurveFromLevel(int level);

// g(τ): acceleration as a fraction of the average. τ is clamped to [0, 1].
double sCurveAcceleration(SCurve shape, double tau);
// G(τ) = ∫₀^τ g: the velocity change so far as a fraction of the segment's (G(1) = 1).
double sCurveVelocity(SCurve shape, double tau);
// H(τ) = ∫₀^τ G: the distance from acceleration so far, in units of A·T² (H(1) = 1/2 for every shape).
double sCurvePosition(SCurve shape, double tau);
// The highest g over the segment.
double sCurvePeak(SCurve shape);

} // namespace drive_core::motion
