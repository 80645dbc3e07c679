#pragma once
// Four floats worked on element by element with IEEE-754's basic operations only, so
// each element gets the bits its scalar form gives (docs/DETERMINISM.md, "SIMD"): SSE2
// on x86-64, a plain loop over the four elsewhere. Nothing here reorders or fuses.
#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace sim {

#if defined(__SSE2__)

struct Float4 {
    __m128 v;
    static Float4 load(const float* p) { return {_mm_loadu_ps(p)}; }
    static Float4 splat(float x) { return {_mm_set1_ps(x)}; }
    void store(float* p) const { _mm_storeu_ps(p, v); }
    friend Float4 operator+(Float4 a, Float4 b) { return {_mm_add_ps(a.v, b.v)}; }
    friend Float4 operator-(Float4 a, Float4 b) { return {_mm_sub_ps(a.v, b.v)}; }
    friend Float4 operator*(Float4 a, Float4 b) { return {_mm_mul_ps(a.v, b.v)}; }
    friend Float4 operator/(Float4 a, Float4 b) { return {_mm_div_ps(a.v, b.v)}; }
    friend Float4 sqrt(Float4 a) { return {_mm_sqrt_ps(a.v)}; }
};

// A per-element comparison result.
struct Mask4 {
    __m128 m;
    // Bit k set where element k is true.
    int bits() const { return _mm_movemask_ps(m); }
    friend Mask4 operator&(Mask4 a, Mask4 b) { return {_mm_and_ps(a.m, b.m)}; }
};
inline Mask4 operator<(Float4 a, Float4 b) { return {_mm_cmplt_ps(a.v, b.v)}; }
inline Mask4 operator>(Float4 a, Float4 b) { return {_mm_cmpgt_ps(a.v, b.v)}; }
// yes where the mask is set, no elsewhere.
inline Float4 select(Mask4 m, Float4 yes, Float4 no) {
    return {_mm_or_ps(_mm_and_ps(m.m, yes.v), _mm_andnot_ps(m.m, no.v))};
}
// Rows to columns: a[k], b[k], c[k], d[k] become element 0..3 of the k-th result.
inline void transpose(Float4& a, Float4& b, Float4& c, Float4& d) { _MM_TRANSPOSE4_PS(a.v, b.v, c.v, d.v); }

#else

struct Float4 {
    float e[4];
    static Float4 load(const float* p) { return {{p[0], p[1], p[2], p[3]}}; }
    static Float4 splat(float x) { return {{x, x, x, x}}; }
    void store(float* p) const {
        for (int k = 0; k < 4; ++k) p[k] = e[k];
    }
    template <class Op>
    static Float4 each(Float4 a, Float4 b, Op op) {
        Float4 r;
        for (int k = 0; k < 4; ++k) r.e[k] = op(a.e[k], b.e[k]);
        return r;
    }
    friend Float4 operator+(Float4 a, Float4 b) { return each(a, b, [](float x, float y) { return x + y; }); }
    friend Float4 operator-(Float4 a, Float4 b) { return each(a, b, [](float x, float y) { return x - y; }); }
    friend Float4 operator*(Float4 a, Float4 b) { return each(a, b, [](float x, float y) { return x * y; }); }
    friend Float4 operator/(Float4 a, Float4 b) { return each(a, b, [](float x, float y) { return x / y; }); }
    friend Float4 sqrt(Float4 a) { return each(a, a, [](float x, float) { return std::sqrt(x); }); }
};

struct Mask4 {
    bool e[4];
    int bits() const { return int(e[0]) | int(e[1]) << 1 | int(e[2]) << 2 | int(e[3]) << 3; }
    friend Mask4 operator&(Mask4 a, Mask4 b) {
        return {{a.e[0] && b.e[0], a.e[1] && b.e[1], a.e[2] && b.e[2], a.e[3] && b.e[3]}};
    }
};
inline Mask4 operator<(Float4 a, Float4 b) {
    return {{a.e[0] < b.e[0], a.e[1] < b.e[1], a.e[2] < b.e[2], a.e[3] < b.e[3]}};
}
inline Mask4 operator>(Float4 a, Float4 b) { return b < a; }
inline Float4 select(Mask4 m, Float4 yes, Float4 no) {
    Float4 r;
    for (int k = 0; k < 4; ++k) r.e[k] = m.e[k] ? yes.e[k] : no.e[k];
    return r;
}
inline void transpose(Float4& a, Float4& b, Float4& c, Float4& d) {
    Float4 r[4] = {a, b, c, d}, t[4];
    for (int k = 0; k < 4; ++k)
        for (int m = 0; m < 4; ++m) t[k].e[m] = r[m].e[k];
    a = t[0], b = t[1], c = t[2], d = t[3];
}

#endif

}  // namespace sim
