// sim/core/DetMath.h against the C library's double functions over the ranges its header
// documents. A float function's error is measured in float ulps of the exact value (the
// library's double result stands for it: its own error is far below a float ulp); a double
// function's in double ulps of the library's result. The bounds asserted are the header's;
// each test prints what it measured.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <vector>

#include "sim/core/DetMath.h"

namespace det = sim::det;

namespace {

constexpr float kInfF = std::numeric_limits<float>::infinity();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The gap between consecutive floats at the magnitude of v (subnormal spacing below 2^-126).
double float_ulp(double v) {
    int k = 0;
    std::frexp(v, &k);  // |v| in [2^(k-1), 2^k)
    return std::ldexp(1.0, std::max(k - 24, -149));
}

double double_ulp(double v) {
    int k = 0;
    std::frexp(v, &k);
    return std::ldexp(1.0, std::max(k - 53, -1074));
}

struct Measured {
    double worst = 0.0;  // in ulps
    double at_x = 0.0, at_y = 0.0, got = 0.0, want = 0.0;
    size_t samples = 0, not_nearest = 0;
    // Keeps the worst error seen (a NaN error counts as worse than any).
    void note(double error, double x, double y, double got_value, double want_value) {
        if (error <= worst) return;
        worst = error;
        at_x = x;
        at_y = y;
        got = got_value;
        want = want_value;
    }
};

// NaN must give NaN; infinities, zeros and results that round to them must match
// exactly, signs included; anything else is measured.
void measure_float(Measured& m, double x, double y, float got, double want) {
    ++m.samples;
    if (std::isnan(want)) {
        EXPECT_TRUE(std::isnan(got)) << "at (" << x << ", " << y << "): got " << got << ", want NaN";
        return;
    }
    const float nearest = float(want);
    if (std::isinf(nearest) || nearest == 0.0f) {
        EXPECT_EQ(std::bit_cast<uint32_t>(got), std::bit_cast<uint32_t>(nearest))
            << "at (" << x << ", " << y << "): got " << got << ", want " << want;
        return;
    }
    if (got != nearest) ++m.not_nearest;
    m.note(std::fabs(double(got) - want) / float_ulp(want), x, y, got, want);
}

void measure_double(Measured& m, double x, double y, double got, double want) {
    ++m.samples;
    if (std::isnan(want)) {
        EXPECT_TRUE(std::isnan(got)) << "at (" << x << ", " << y << "): got " << got << ", want NaN";
        return;
    }
    if (std::isinf(want) || want == 0.0) {
        EXPECT_EQ(got, want) << "at (" << x << ", " << y << ")";
        return;
    }
    if (got != want) ++m.not_nearest;
    m.note(std::fabs(got - want) / double_ulp(want), x, y, got, want);
}

void report(const char* what, const char* unit, const Measured& m) {
    std::printf("%-34s max %.4f %s ulp at (%.9g, %.9g); %zu of %zu samples differ from libm's\n", what, m.worst,
                unit, m.at_x, m.at_y, m.not_nearest, m.samples);
}

// About n positive floats from lo to hi stepping through their bits: every magnitude alike.
std::vector<float> by_magnitude(float lo, float hi, size_t n) {
    std::vector<float> v;
    const uint32_t from = std::bit_cast<uint32_t>(lo), to = std::bit_cast<uint32_t>(hi);
    const uint32_t step = std::max<uint32_t>(1, uint32_t((to - from) / n));
    for (uint64_t bits = from; bits <= to; bits += step) v.push_back(std::bit_cast<float>(uint32_t(bits)));
    v.push_back(hi);
    return v;
}

// n + 1 evenly spaced floats from lo to hi.
std::vector<float> evenly(float lo, float hi, size_t n) {
    std::vector<float> v;
    for (size_t i = 0; i <= n; ++i) v.push_back(float(double(lo) + (double(hi) - double(lo)) * double(i) / double(n)));
    return v;
}

// by_magnitude(lo, hi) with both signs, then evenly(-lin, lin), then the special values.
std::vector<float> arguments(float lo, float hi, size_t n_magnitude, float lin, size_t n_even) {
    std::vector<float> v = by_magnitude(lo, hi, n_magnitude);
    const size_t half = v.size();
    for (size_t i = 0; i < half; ++i) v.push_back(-v[i]);
    for (float x : evenly(-lin, lin, n_even)) v.push_back(x);
    for (float x : {0.0f, -0.0f, kInfF, -kInfF, std::numeric_limits<float>::quiet_NaN(),
                    std::numeric_limits<float>::denorm_min(), -std::numeric_limits<float>::denorm_min(),
                    std::numeric_limits<float>::max(), -std::numeric_limits<float>::max()})
        v.push_back(x);
    return v;
}

template <class Det, class Ref>
Measured unary(const std::vector<float>& xs, Det det_fn, Ref ref_fn) {
    Measured m;
    for (float x : xs) measure_float(m, x, 0.0, det_fn(x), ref_fn(double(x)));
    return m;
}

constexpr double kFloatBound = 0.501;  // the header's: correctly rounded bar a few thousandths

TEST(DetMath, SinCosAndTanAreWithinTheBoundUpTo2To20) {
    // Past 2^20 only finiteness is asked: the reduction is exact only below it.
    std::vector<float> xs = arguments(1e-30f, 1048576.0f, 300000, 20.0f, 200000);
    xs.erase(std::remove_if(xs.begin(), xs.end(), [](float x) { return std::fabs(x) > 1048576.0f; }), xs.end());
    const Measured s = unary(xs, [](float x) { return det::sin(x); }, [](double x) { return std::sin(x); });
    const Measured c = unary(xs, [](float x) { return det::cos(x); }, [](double x) { return std::cos(x); });
    const Measured t = unary(xs, [](float x) { return det::tan(x); }, [](double x) { return std::tan(x); });
    report("sin, |x| <= 2^20", "float", s);
    report("cos, |x| <= 2^20", "float", c);
    report("tan, |x| <= 2^20", "float", t);
    EXPECT_LE(s.worst, kFloatBound) << "sin(" << s.at_x << ") = " << s.got << ", want " << s.want;
    EXPECT_LE(c.worst, kFloatBound) << "cos(" << c.at_x << ") = " << c.got << ", want " << c.want;
    EXPECT_LE(t.worst, kFloatBound) << "tan(" << t.at_x << ") = " << t.got << ", want " << t.want;
    // sincos is sin and cos, bit for bit.
    for (float x : xs) {
        float sn = 0.0f, cs = 0.0f;
        det::sincos(x, sn, cs);
        ASSERT_EQ(std::bit_cast<uint32_t>(sn), std::bit_cast<uint32_t>(det::sin(x))) << x;
        ASSERT_EQ(std::bit_cast<uint32_t>(cs), std::bit_cast<uint32_t>(det::cos(x))) << x;
    }
    EXPECT_TRUE(std::signbit(det::sin(-0.0f)));
    EXPECT_EQ(det::cos(0.0f), 1.0f);
    EXPECT_TRUE(std::isnan(det::sin(kInfF)) && std::isnan(det::cos(-kInfF)) && std::isnan(det::tan(kInfF)));
    for (float x : {3e9f, -1e20f, 3e38f}) EXPECT_TRUE(std::isfinite(det::sin(x)) && std::fabs(det::sin(x)) <= 1.0f) << x;
}

TEST(DetMath, AtanAndAsinAreWithinTheBound) {
    const Measured a = unary(arguments(1e-38f, 3e38f, 400000, 4.0f, 200000), [](float x) { return det::atan(x); },
                             [](double x) { return std::atan(x); });
    std::vector<float> xs = arguments(1e-38f, 1.0f, 300000, 1.0f, 200000);
    for (float x : {1.0000001f, -1.5f, 2.0f}) xs.push_back(x);  // outside: NaN
    const Measured s = unary(xs, [](float x) { return det::asin(x); }, [](double x) { return std::asin(x); });
    report("atan, all floats", "float", a);
    report("asin, [-1, 1]", "float", s);
    EXPECT_LE(a.worst, kFloatBound) << "atan(" << a.at_x << ") = " << a.got << ", want " << a.want;
    EXPECT_LE(s.worst, kFloatBound) << "asin(" << s.at_x << ") = " << s.got << ", want " << s.want;
    EXPECT_EQ(det::asin(1.0f), float(std::asin(1.0)));
    EXPECT_EQ(det::atan(kInfF), float(std::atan(kInf)));
}

TEST(DetMath, Atan2IsWithinTheBoundInEveryQuadrantWithIeeeSpecialCases) {
    std::vector<float> coords = by_magnitude(1e-30f, 1e30f, 700);
    const size_t half = coords.size();
    for (size_t i = 0; i < half; ++i) coords.push_back(-coords[i]);
    for (float v : evenly(-3.0f, 3.0f, 300)) coords.push_back(v);
    for (float v : {0.0f, -0.0f, kInfF, -kInfF, std::numeric_limits<float>::quiet_NaN()}) coords.push_back(v);
    Measured m;
    for (float y : coords)
        for (float x : coords) measure_float(m, y, x, det::atan2(y, x), std::atan2(double(y), double(x)));
    report("atan2, a grid over all floats", "float", m);
    EXPECT_LE(m.worst, kFloatBound) << "atan2(" << m.at_x << ", " << m.at_y << ") = " << m.got << ", want " << m.want;
    EXPECT_TRUE(std::signbit(det::atan2(-0.0f, 1.0f)));
    EXPECT_EQ(det::atan2(0.0f, -0.0f), float(std::atan2(0.0, -0.0)));  // pi
    EXPECT_EQ(det::atan2(-kInfF, -kInfF), float(std::atan2(-kInf, -kInf)));
}

TEST(DetMath, TanhExpAndCbrtAreWithinTheBound) {
    const Measured th = unary(arguments(1e-38f, 3e38f, 300000, 12.0f, 200000), [](float x) { return det::tanh(x); },
                              [](double x) { return std::tanh(x); });
    std::vector<float> xs = arguments(1e-38f, 200.0f, 300000, 104.0f, 300000);
    const Measured ex = unary(xs, [](float x) { return det::exp(x); }, [](double x) { return std::exp(x); });
    const Measured cb = unary(arguments(1e-45f, 3e38f, 400000, 30.0f, 100000), [](float x) { return det::cbrt(x); },
                              [](double x) { return std::cbrt(x); });
    report("tanh, all floats", "float", th);
    report("exp, all floats", "float", ex);
    report("cbrt, all floats", "float", cb);
    EXPECT_LE(th.worst, kFloatBound) << "tanh(" << th.at_x << ") = " << th.got << ", want " << th.want;
    EXPECT_LE(ex.worst, kFloatBound) << "exp(" << ex.at_x << ") = " << ex.got << ", want " << ex.want;
    EXPECT_LE(cb.worst, kFloatBound) << "cbrt(" << cb.at_x << ") = " << cb.got << ", want " << cb.want;
    // Exact cubes stay exact.
    for (float r : {2.0f, 3.0f, 0.5f, 10.0f, -4.0f}) EXPECT_EQ(det::cbrt(r * r * r), r);
    EXPECT_EQ(det::exp(0.0f), 1.0f);
    EXPECT_EQ(det::tanh(kInfF), 1.0f);
}

TEST(DetMath, DoubleExpLogAndPowAreWithinTheBound) {
    Measured ex, lg, pw;
    for (int i = 0; i <= 400000; ++i) {
        const double x = -745.0 + (709.7 + 745.0) * double(i) / 400000.0;
        measure_double(ex, x, 0.0, det::exp(x), std::exp(x));
    }
    for (float f : by_magnitude(1e-38f, 3e38f, 400000)) {
        const double x = double(f) * (1.0 + 0x1p-30);  // not only floats
        measure_double(lg, x, 0.0, det::log(x), std::log(x));
    }
    measure_double(lg, 5e-324, 0.0, det::log(5e-324), std::log(5e-324));  // subnormal
    double worst_allowed = 0.0;
    for (int i = 1; i <= 600; ++i)
        for (int j = 0; j <= 600; ++j) {
            const double x = 4.0 * double(i) / 600.0, y = -8.0 + 16.0 * double(j) / 600.0;
            const double want = std::pow(x, y);
            const double before = pw.worst;
            measure_double(pw, x, y, det::pow(x, y), want);
            const double allowed = 2.0 + 4.0 * std::fabs(y * std::log(x));
            if (pw.worst > before) worst_allowed = allowed;
            EXPECT_LE(std::fabs(det::pow(x, y) - want) / double_ulp(want), allowed) << "pow(" << x << ", " << y << ")";
        }
    report("exp(double), [-745, 709.7]", "double", ex);
    report("log(double), all doubles > 0", "double", lg);
    report("pow(double), (0, 4] x [-8, 8]", "double", pw);
    std::printf("pow's worst case was allowed %.2f ulp\n", worst_allowed);
    EXPECT_LE(ex.worst, 2.0) << "exp(" << ex.at_x << ")";
    EXPECT_LE(lg.worst, 2.0) << "log(" << lg.at_x << ")";
    EXPECT_EQ(det::pow(0.0, 2.0), 0.0);
    EXPECT_EQ(det::pow(2.0, 0.0), 1.0);
    EXPECT_TRUE(std::isnan(det::pow(-2.0, 2.0)));
    EXPECT_EQ(det::log(1.0), 0.0);
    EXPECT_EQ(det::exp(1000.0), kInf);
    EXPECT_EQ(det::exp(-1000.0), 0.0);
    EXPECT_TRUE(std::isnan(det::log(-1.0)) && std::isnan(det::exp(kNaN)));
}

}  // namespace
