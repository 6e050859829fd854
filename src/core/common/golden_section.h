#pragma once
/// @file
/// @brief Golden-section search: the one way the core narrows a bracket round a minimum (or,
/// of −f, a maximum) of a function it can only evaluate.

namespace cam {

/// @brief The last bracket [lo, hi] of a golden-section search and its two inner points with
/// their values (x1 < x2).
struct GoldenSection {
    double lo, hi;
    double x1, f1;
    double x2, f2;
};

/// @brief Narrows [lo, hi] towards a minimum of f while keepGoing(lo, hi, step) holds (step
/// counts from 0): each step keeps the side of the lower inner point (on a tie the left one)
/// and evaluates f once, at the new inner point.
template <class F, class KeepGoing>
GoldenSection goldenSectionMin(F&& f, double lo, double hi, KeepGoing&& keepGoing) {
    constexpr double g = 0.6180339887498949;  // (√5 − 1) / 2
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    double f1 = f(x1), f2 = f(x2);
    for (int step = 0; keepGoing(lo, hi, step); ++step) {
        if (f1 <= f2) {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - g * (hi - lo);
            f1 = f(x1);
        } else {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + g * (hi - lo);
            f2 = f(x2);
        }
    }
    return {lo, hi, x1, f1, x2, f2};
}

}  // namespace cam
