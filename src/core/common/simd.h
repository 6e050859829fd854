#pragma once
/// @file
/// @brief What lets the sampling loops use the running CPU's vector units: GCC function
/// multiversioning (each marked loop compiled for AVX-512, AVX2 and plain x86-64, the best
/// chosen at load time, so a package built for any x86-64 still uses them) and glibc's vector
/// atan2 and cos (libmvec, within 4 ulp), which GCC calls only for math functions declared
/// "simd".
/// Elsewhere the marks are empty and the loops stay plain, with the same results to rounding.

#include <cmath>

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define CAMWRIGHT_MULTIVERSION \
    __attribute__((flatten, target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 35))
// libmvec has had atan2 since glibc 2.35; <math.h> declares it "simd" only under -ffast-math,
// which the core must not use (it relies on infinities and NaN tests).
extern "C" __attribute__((simd("notinbranch"))) double atan2(double, double) noexcept;
// And cos (in libmvec since glibc 2.22): the forces divide by cos α of every sample.
extern "C" __attribute__((simd("notinbranch"))) double cos(double) noexcept;
#endif
#else
#define CAMWRIGHT_MULTIVERSION
#endif
