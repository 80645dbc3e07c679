#pragma once
// The sim's transcendental functions, written here with IEEE-754 basic operations only
// (+, -, *, /, sqrt, and the exact float<->double conversions), so that they give the
// same bits on every compiler, C library and CPU. libm's sin, exp, atan2, ... differ in
// their last bits between glibc versions, other C libraries and architectures, and one
// differing bit desyncs a replay. The sim calls no libm function but the exact ones
// (sqrt, fabs, floor, ceil, trunc, round, lround, fmod, fmin, fmax, copysign);
// tests/det_math_symbols.cmake reads the sim library's symbol table to keep it so.
//
// The float functions work in double and round once at the end. Accuracy, measured
// against glibc's double functions rounded to float (tests/det_math_test.cpp, which
// asserts the bounds), in float ulps of the exact result:
//   sin, cos, sincos   |x| <= 2^20      <= 0.501 ulp (|x| > 2^20: the same bits everywhere,
//                                        but the reduction is no longer accurate)
//   tan                |x| <= 2^20      <= 0.501 ulp
//   asin               [-1, 1]          <= 0.501 ulp (NaN outside)
//   atan, atan2        all floats       <= 0.501 ulp (IEEE special cases of atan2 for
//                                        zeros and infinities)
//   tanh               all floats       <= 0.501 ulp
//   exp                all floats       <= 0.501 ulp (overflow to inf, underflow to 0)
//   cbrt               all floats       <= 0.501 ulp
// The double functions, in double ulps:
//   exp(double)        [-745, 709.7]    <= 2 ulp
//   log(double)        x > 0            <= 2 ulp
//   pow(double, double) x >= 0          <= (2 + 4 |y ln x|) ulp (x < 0 gives NaN: no
//                                        integer-power case, the sim has none)
// Only double overloads that exist are declared: a double passed to a float function
// is a compile error, not a silent narrowing.
#if defined(__FAST_MATH__)
#error "the sim must not be built with -ffast-math: it reorders and contracts floating-point operations, and replays desync (docs/DETERMINISM.md)"
#endif
#if defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__
#error "the sim must not be built with -ffinite-math-only (docs/DETERMINISM.md)"
#endif

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>

#if FLT_EVAL_METHOD != 0
#error "the sim needs float and double operations evaluated in their own precision (SSE2 on x86, not x87)"
#endif

namespace sim::det {

namespace detail {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kPi = 0x1.921fb54442d18p+1;
constexpr double kPiOver2 = 0x1.921fb54442d18p+0;
constexpr double kPiOver4 = 0x1.921fb54442d18p-1;
constexpr double kPiOver6 = 0x1.0c152382d7366p-1;
constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;
constexpr double kSqrt3 = 0x1.bb67ae8584caap+0;
constexpr double kTanPiOver12 = 0x1.126145e9ecd56p-2;  // 2 - sqrt(3)
// pi/2 in three parts: the first two hold 33 bits each, so k * part is exact for
// |k| < 2^20 and x - k pi/2 keeps its accuracy (Cody and Waite).
constexpr double kPiOver2Part1 = 0x1.921fb544p+0;
constexpr double kPiOver2Part2 = 0x1.0b4611a6p-34;
constexpr double kPiOver2Part3 = 0x1.3198a2e037073p-69;
// ln 2 in two parts, the first with 32 bits: k * part1 is exact for any exponent k.
constexpr double kLn2Part1 = 0x1.62e42feep-1;
constexpr double kLn2Part2 = 0x1.a39ef35793c76p-33;
constexpr double kInvLn2 = 0x1.71547652b82fep+0;
constexpr double kSqrt2 = 0x1.6a09e667f3bcdp+0;
// Below this magnitude sin, tan, asin, atan and tanh of a float round to the float itself.
constexpr double kTiny = 0x1p-12;

// The nearest integer, ties to even, for |x| < 2^51 (adding 1.5 * 2^52 drops the fraction).
inline double nearest_integer(double x) {
    constexpr double kShift = 0x1.8p52;
    return (x + kShift) - kShift;
}

// 2^k for -1022 <= k <= 1023, built from its bits.
inline double power_of_two(int k) { return std::bit_cast<double>(uint64_t(int64_t(k) + 1023) << 52); }

// sin and cos for |r| <= pi/4 (plus rounding): Taylor series to r^15 and r^16, whose
// remainders are below 2^-54 of the result there.
inline double sin_kernel(double r) {
    const double r2 = r * r;
    const double p =
        -1.0 / 6.0 +
        r2 * (1.0 / 120.0 +
              r2 * (-1.0 / 5040.0 +
                    r2 * (1.0 / 362880.0 +
                          r2 * (-1.0 / 39916800.0 + r2 * (1.0 / 6227020800.0 + r2 * (-1.0 / 1307674368000.0))))));
    return r + r * (r2 * p);
}

inline double cos_kernel(double r) {
    const double r2 = r * r;
    const double p =
        1.0 / 24.0 +
        r2 * (-1.0 / 720.0 +
              r2 * (1.0 / 40320.0 +
                    r2 * (-1.0 / 3628800.0 +
                          r2 * (1.0 / 479001600.0 + r2 * (-1.0 / 87178291200.0 + r2 * (1.0 / 20922789888000.0))))));
    return 1.0 - 0.5 * r2 + (r2 * r2) * p;
}

// x = quadrant * pi/2 + r with |r| <= pi/4 (slightly more past 2^20).
struct Reduced {
    double r;
    unsigned quadrant;  // mod 4
};

inline Reduced reduce_quarter_turns(float xf) {
    double x = xf;
    if (std::fabs(x) <= kPiOver4) return {x, 0};
    if (!std::isfinite(x)) return {kNaN, 0};
    // Past 2^30 the quotient no longer fits the scheme; fmod is exact, so the result is
    // still the same everywhere (though not accurate: the sim has no such angles).
    if (!(std::fabs(x) < 0x1p30)) x = std::fmod(x, 4.0 * kPiOver2Part1);
    const double k = nearest_integer(x * kTwoOverPi);
    const double r = ((x - k * kPiOver2Part1) - k * kPiOver2Part2) - k * kPiOver2Part3;
    return {r, unsigned(int64_t(k)) & 3u};
}

struct SinCos {
    double s, c;
};

inline SinCos sincos(float x) {
    const Reduced q = reduce_quarter_turns(x);
    const double s = sin_kernel(q.r), c = cos_kernel(q.r);
    switch (q.quadrant) {
        case 0: return {s, c};
        case 1: return {c, -s};
        case 2: return {-s, -c};
        default: return {-c, s};
    }
}

// atan for a >= 0 (inf included): reduced to [0, 1] by atan(a) = pi/2 - atan(1/a), then to
// |t| <= 2 - sqrt(3) by atan(a) = pi/6 + atan((sqrt(3) a - 1) / (a + sqrt(3))); the Taylor
// series to t^25 leaves a remainder below 2^-56 there.
inline double atan_nonnegative(double a) {
    const bool inverted = a > 1.0;
    if (inverted) a = 1.0 / a;
    const bool shifted = a > kTanPiOver12;
    if (shifted) a = (a * kSqrt3 - 1.0) / (a + kSqrt3);
    const double a2 = a * a;
    constexpr double kOdd[] = {-1.0 / 3.0,  1.0 / 5.0,  -1.0 / 7.0,  1.0 / 9.0,  -1.0 / 11.0, 1.0 / 13.0,
                               -1.0 / 15.0, 1.0 / 17.0, -1.0 / 19.0, 1.0 / 21.0, -1.0 / 23.0, 1.0 / 25.0};
    double p = kOdd[11];
    for (int n = 10; n >= 0; --n) p = kOdd[n] + a2 * p;
    double v = a + a * (a2 * p);
    if (shifted) v += kPiOver6;
    if (inverted) v = kPiOver2 - v;
    return v;
}

inline bool is_nan(double x) { return x != x; }

}  // namespace detail

// e^x in double. |x| small enough to reach subnormal results rounds twice (still the
// same everywhere).
inline double exp(double x) {
    using namespace detail;
    if (is_nan(x)) return x;
    if (x > 0x1.62e42fefa39efp+9) return kInf;
    if (x < -745.2) return 0.0;
    const double k = nearest_integer(x * kInvLn2);
    const double r = (x - k * kLn2Part1) - k * kLn2Part2;  // |r| <= ln2 / 2 (+ rounding)
    // Taylor series to r^13: remainder below 2^-57 for |r| <= 0.35.
    double p = 1.0 / 6227020800.0;
    constexpr double kInverseFactorials[] = {1.0,
                                             1.0,
                                             1.0 / 2.0,
                                             1.0 / 6.0,
                                             1.0 / 24.0,
                                             1.0 / 120.0,
                                             1.0 / 720.0,
                                             1.0 / 5040.0,
                                             1.0 / 40320.0,
                                             1.0 / 362880.0,
                                             1.0 / 3628800.0,
                                             1.0 / 39916800.0,
                                             1.0 / 479001600.0};
    for (int n = 12; n >= 0; --n) p = kInverseFactorials[n] + r * p;
    int e = int(k);
    if (e > 1023) {
        p *= 0x1p1023;
        e -= 1023;
    } else if (e < -1022) {
        p *= 0x1p-600;
        e += 600;
    }
    return p * power_of_two(e);
}

// Natural logarithm in double: x = m 2^e with m in [sqrt(1/2), sqrt(2)], and
// ln m = 2 atanh(s), s = (m - 1) / (m + 1), |s| <= 0.172, by its series to s^23.
inline double log(double x) {
    using namespace detail;
    if (is_nan(x) || x < 0.0) return kNaN;
    if (x == 0.0) return -kInf;
    if (x == kInf) return kInf;
    int bias = 0;
    if (x < 0x1p-1022) {  // subnormal: make it normal first
        x *= 0x1p54;
        bias = -54;
    }
    const uint64_t bits = std::bit_cast<uint64_t>(x);
    int e = int((bits >> 52) & 0x7ff) - 1023 + bias;
    double m = std::bit_cast<double>((bits & 0x000fffffffffffffull) | 0x3ff0000000000000ull);
    if (m > kSqrt2) {
        m *= 0.5;
        ++e;
    }
    const double s = (m - 1.0) / (m + 1.0), s2 = s * s;
    constexpr double kOdd[] = {1.0 / 3.0,  1.0 / 5.0,  1.0 / 7.0,  1.0 / 9.0,  1.0 / 11.0,
                               1.0 / 13.0, 1.0 / 15.0, 1.0 / 17.0, 1.0 / 19.0, 1.0 / 21.0, 1.0 / 23.0};
    double p = kOdd[10];
    for (int n = 9; n >= 0; --n) p = kOdd[n] + s2 * p;
    const double ln_m = 2.0 * s + 2.0 * s * (s2 * p);
    const double de = double(e);
    return de * kLn2Part1 + (de * kLn2Part2 + ln_m);
}

// x^y for x >= 0, as e^(y ln x); NaN for x < 0.
inline double pow(double x, double y) {
    using namespace detail;
    if (y == 0.0 || x == 1.0) return 1.0;
    if (is_nan(x) || is_nan(y) || x < 0.0) return kNaN;
    if (x == 0.0) return y > 0.0 ? 0.0 : kInf;
    return det::exp(y * det::log(x));
}

inline float sin(float x) {
    if (std::fabs(x) < detail::kTiny) return x;
    return float(detail::sincos(x).s);
}

inline float cos(float x) { return float(detail::sincos(x).c); }

// Both from one reduction; the same bits as sin(x) and cos(x).
inline void sincos(float x, float& s, float& c) {
    const detail::SinCos sc = detail::sincos(x);
    s = std::fabs(x) < detail::kTiny ? x : float(sc.s);
    c = float(sc.c);
}

inline float tan(float x) {
    if (std::fabs(x) < detail::kTiny) return x;
    const detail::Reduced q = detail::reduce_quarter_turns(x);
    const double s = detail::sin_kernel(q.r), c = detail::cos_kernel(q.r);
    return float(q.quadrant % 2 ? -c / s : s / c);
}

inline float atan(float x) {
    if (!(std::fabs(x) >= detail::kTiny)) return x;  // NaN too
    const double v = detail::atan_nonnegative(std::fabs(double(x)));
    return float(x < 0.0f ? -v : v);
}

// The angle of (x, y) in (-pi, pi], with IEEE's signed zeros and infinities.
inline float atan2(float y, float x) {
    using namespace detail;
    if (is_nan(x) || is_nan(y)) return x + y;
    const double ax = std::fabs(double(x)), ay = std::fabs(double(y));
    double a;
    if (ax == 0.0 && ay == 0.0) a = 0.0;
    else if (ax == kInf && ay == kInf) a = kPiOver4;
    else a = atan_nonnegative(ay / ax);
    if (std::signbit(x)) a = kPi - a;
    return float(std::signbit(y) ? -a : a);
}

inline float asin(float x) {
    using namespace detail;
    if (!(std::fabs(x) >= kTiny)) return x;  // NaN too
    if (std::fabs(x) > 1.0f) return float(kNaN);
    const double d = std::fabs(double(x));
    const double v = atan_nonnegative(d / std::sqrt((1.0 - d) * (1.0 + d)));
    return float(x < 0.0f ? -v : v);
}

inline float exp(float x) { return float(det::exp(double(x))); }

inline float tanh(float x) {
    using namespace detail;
    if (!(std::fabs(x) >= kTiny)) return x;  // NaN too
    const double a = std::fabs(double(x));
    double v;
    if (a < 0.125) {
        // Taylor series to a^15 (remainder below 2^-60 here): 1 - e^-2a cancels near 0.
        const double a2 = a * a;
        const double p =
            -1.0 / 3.0 +
            a2 * (2.0 / 15.0 +
                  a2 * (-17.0 / 315.0 +
                        a2 * (62.0 / 2835.0 +
                              a2 * (-1382.0 / 155925.0 + a2 * (21844.0 / 6081075.0 + a2 * (-929569.0 / 638512875.0))))));
        v = a + a * (a2 * p);
    } else if (a > 10.0) {
        v = 1.0;  // 1 - tanh(10) = 4e-9 is below half a float ulp of 1
    } else {
        const double e = det::exp(-2.0 * a);
        v = (1.0 - e) / (1.0 + e);
    }
    return float(x < 0.0f ? -v : v);
}

inline float cbrt(float x) {
    if (x == 0.0f || !std::isfinite(x)) return x + x;  // signed zero, inf, NaN
    const double a = std::fabs(double(x));
    // A first guess from the exponent (the bits' high word divided by 3, rebiased: within
    // 4%), then Newton's y - (y - a / y^2) / 3 four times: 2^-5 -> 2^-80, past double.
    const uint64_t bits = std::bit_cast<uint64_t>(a);
    double y = std::bit_cast<double>(uint64_t(uint32_t(bits >> 32) / 3u + 715094163u) << 32);
    for (int i = 0; i < 4; ++i) y = y - (y - a / (y * y)) / 3.0;
    return float(x < 0.0f ? -y : y);
}

// Doubles into the float functions are refused: convert on purpose.
double sin(double) = delete;
double cos(double) = delete;
double tan(double) = delete;
double atan(double) = delete;
double atan2(double, double) = delete;
double asin(double) = delete;
double tanh(double) = delete;
double cbrt(double) = delete;

}  // namespace sim::det
