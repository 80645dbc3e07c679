#include "sim/rain/ParticleCollider.h"

#include <cmath>
#include <cstddef>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace sim {

#if defined(__SSE2__)
namespace {

__m128 select(__m128 mask, __m128 yes, __m128 no) { return _mm_or_ps(_mm_and_ps(mask, yes), _mm_andnot_ps(mask, no)); }

}  // namespace
#endif

void ParticleCollider::collide(std::vector<WaterParticle>& particles, float radius_m, float restitution) {
    const float two_r = 2.0f * radius_m, two_r2 = two_r * two_r;
    const float bounce = 1.0f + restitution;
    buckets_.build(particles, two_r);
    const int32_t n = buckets_.slots();
    push_.assign(size_t(n), glm::vec2(0.0f));
    const size_t most = size_t(n) + 4;  // one bucket's neighbourhood, padded
    for (std::vector<float>* v : {&near_u_, &near_v_, &push_u_, &push_v_})
        if (v->size() < most) v->resize(most);
    for (std::vector<int32_t>* v : {&near_slot_, &near_index_})
        if (v->size() < most) v->resize(most);

#if defined(__SSE2__)
    const __m128 reach2 = _mm_set1_ps(two_r2), reach = _mm_set1_ps(two_r), bounce4 = _mm_set1_ps(bounce);
    const __m128 half = _mm_set1_ps(0.5f), apart = _mm_set1_ps(1e-7f), plus = _mm_set1_ps(1.0f), minus = _mm_set1_ps(-1.0f);
#endif
    for (int32_t k = 0; k < buckets_.buckets(); ++k) {
        const int32_t first = buckets_.begin(k), last = buckets_.end(k);
        if (first == last) continue;
        // The bucket's slots, then those of the buckets ahead: slot a meets the ones
        // after its own place in this list.
        size_t count = 0;
        auto gather = [&](int32_t b0, int32_t b1) {
            for (int32_t b = b0; b < b1; ++b, ++count) {
                const glm::vec2 p = buckets_.position(b);
                near_u_[count] = p.x;
                near_v_[count] = p.y;
                near_slot_[count] = b;
                near_index_[count] = buckets_.particle(b);
            }
        };
        gather(first, last);
        buckets_.for_each_ahead(k, gather);
        for (size_t c = count; c < count + 3; ++c) {  // padding, never summed
            near_u_[c] = near_v_[c] = 0.0f;
            near_index_[c] = 0;
        }
        for (int32_t a = first; a < last; ++a) {
            const size_t from = size_t(a - first) + 1;
            const glm::vec2 pa = buckets_.position(a);
#if defined(__SSE2__)
            const __m128 au = _mm_set1_ps(pa.x), av = _mm_set1_ps(pa.y);
            const __m128i ai = _mm_set1_epi32(buckets_.particle(a));
            for (size_t c = from; c < count; c += 4) {
                const __m128 du = _mm_sub_ps(au, _mm_loadu_ps(&near_u_[c]));
                const __m128 dv = _mm_sub_ps(av, _mm_loadu_ps(&near_v_[c]));
                const __m128 d2 = _mm_add_ps(_mm_mul_ps(du, du), _mm_mul_ps(dv, dv));
                const __m128 touching = _mm_cmpnge_ps(d2, reach2);
                const __m128 dist = _mm_sqrt_ps(d2);
                // Coincident centres part along a direction fixed by their order.
                const __m128 distinct = _mm_cmpgt_ps(dist, apart);
                const __m128i bi = _mm_loadu_si128(reinterpret_cast<const __m128i*>(&near_index_[c]));
                const __m128 a_first = _mm_castsi128_ps(_mm_cmplt_epi32(ai, bi));
                const __m128 dir_u = select(distinct, _mm_div_ps(du, dist), select(a_first, plus, minus));
                const __m128 dir_v = _mm_and_ps(distinct, _mm_div_ps(dv, dist));
                const __m128 size = _mm_mul_ps(_mm_mul_ps(half, _mm_sub_ps(reach, dist)), bounce4);
                _mm_storeu_ps(&push_u_[c], _mm_and_ps(touching, _mm_mul_ps(dir_u, size)));
                _mm_storeu_ps(&push_v_[c], _mm_and_ps(touching, _mm_mul_ps(dir_v, size)));
            }
#else
            // Without SSE (aarch64): the same IEEE operations one lane at a time, and the
            // same +0 where a mask would clear the lane.
            const int32_t ai = buckets_.particle(a);
            for (size_t c = from; c < count; ++c) {
                const float du = pa.x - near_u_[c], dv = pa.y - near_v_[c];
                const float d2 = du * du + dv * dv;
                const bool touching = !(d2 >= two_r2);
                const float dist = std::sqrt(d2);
                const bool distinct = dist > 1e-7f;
                const float dir_u = distinct ? du / dist : (ai < near_index_[c] ? 1.0f : -1.0f);
                const float dir_v = distinct ? dv / dist : 0.0f;
                const float size = (0.5f * (two_r - dist)) * bounce;
                push_u_[c] = touching ? dir_u * size : 0.0f;
                push_v_[c] = touching ? dir_v * size : 0.0f;
            }
#endif
            // Slot a's own push is summed in a register: its partners are other slots.
            glm::vec2 push_a = push_[size_t(a)];
            for (size_t c = from; c < count; ++c) {
                const glm::vec2 push(push_u_[c], push_v_[c]);
                push_a += push;
                push_[size_t(near_slot_[c])] -= push;
            }
            push_[size_t(a)] = push_a;
        }
    }
    for (int32_t a = 0; a < n; ++a) particles[size_t(buckets_.particle(a))].pos_m += push_[size_t(a)];
}

}  // namespace sim
