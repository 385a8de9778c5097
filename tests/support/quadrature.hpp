// quadrature.hpp — numeric references for the fog tests: composite
// Gauss-Legendre quadrature, a sinh-graded variant for peaked integrands,
// golden-section minimisation and bisection. Header-only, test use only;
// nothing here calls the code under test.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace aerial::test {

/// Composite 5-point Gauss-Legendre over `intervals` equal sub-intervals of
/// [a, b] (5 * intervals evaluations). Exact for polynomials of degree 9 on
/// each sub-interval; for the smooth integrands here the error is at the
/// rounding level once a sub-interval spans less than about one e-fold.
template <class F>
double gaussLegendre(F&& f, double a, double b, std::size_t intervals) {
    static constexpr std::array<double, 5> kNodes = {0.0, -0.5384693101056831, 0.5384693101056831,
                                                     -0.9061798459386640, 0.9061798459386640};
    static constexpr std::array<double, 5> kWeights = {
        0.5688888888888889, 0.4786286704993665, 0.4786286704993665, 0.2369268850561891, 0.2369268850561891};
    if (!(b > a) || intervals == 0) {
        return 0.0;
    }
    const double h = (b - a) / static_cast<double>(intervals);
    double sum = 0.0;
    for (std::size_t k = 0; k < intervals; ++k) {
        const double mid = a + (static_cast<double>(k) + 0.5) * h;
        double part = 0.0;
        for (std::size_t j = 0; j < kNodes.size(); ++j) {
            part += kWeights[j] * f(mid + 0.5 * h * kNodes[j]);
        }
        sum += part * 0.5 * h;
    }
    return sum;
}

/// Integral over [a, b] of a function peaked at `centre` with width `width`
/// (> 0): split at the centre, and on each side substitute
/// s = width sinh(sigma) so the peak and the long tails are both resolved.
/// `intervals` Gauss-Legendre sub-intervals per side.
template <class F>
double gaussLegendrePeaked(F&& f, double a, double b, double centre, double width, std::size_t intervals) {
    if (!(b > a)) {
        return 0.0;
    }
    const double c = std::clamp(centre, a, b);
    auto side = [&](double length, double sign) {
        if (!(length > 0.0)) {
            return 0.0;
        }
        const double sigmaMax = std::asinh(length / width);
        return gaussLegendre(
            [&](double sigma) { return f(c + sign * width * std::sinh(sigma)) * width * std::cosh(sigma); },
            0.0, sigmaMax, intervals);
    };
    return side(b - c, 1.0) + side(c - a, -1.0);
}

/// Minimum of a convex (unimodal) function on [a, b] by golden-section
/// search, to the rounding level of t.
template <class F>
double goldenSectionMinimum(F&& f, double a, double b) {
    const double invPhi = 0.6180339887498949;
    double x1 = b - invPhi * (b - a);
    double x2 = a + invPhi * (b - a);
    double f1 = f(x1);
    double f2 = f(x2);
    for (int it = 0; it < 400 && b - a > 0.0; ++it) {
        if (f1 <= f2) {
            b = x2;
            x2 = x1;
            f2 = f1;
            x1 = b - invPhi * (b - a);
            f1 = f(x1);
        } else {
            a = x1;
            x1 = x2;
            f1 = f2;
            x2 = a + invPhi * (b - a);
            f2 = f(x2);
        }
        if (!(x1 < x2)) {
            break;
        }
    }
    return 0.5 * (a + b);
}

/// The point in [a, b] where `inside` changes: inside(a) != inside(b)
/// required. Bisection to the last bit.
template <class Pred>
double bisectBoundary(Pred&& inside, double a, double b) {
    const bool insideA = inside(a);
    for (int it = 0; it < 2000; ++it) {
        const double mid = 0.5 * (a + b);
        if (!(mid > a && mid < b)) {
            break;
        }
        if (inside(mid) == insideA) {
            a = mid;
        } else {
            b = mid;
        }
    }
    return 0.5 * (a + b);
}

}  // namespace aerial::test
