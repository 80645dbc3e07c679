#pragma once
// What the audio tests measure on a render (interleaved stereo at 48 kHz): loudness and
// true peak (libebur128), sample sanity, band levels, onsets and a pitch track. The
// filters are written here, independently of the audio library's.
#include <ebur128.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

namespace audio_test {

inline constexpr int kRate = 48000;
inline constexpr int kTickFrames = kRate / 60;

struct Loudness {
    double integrated_lufs = -HUGE_VAL;
    double true_peak_dbtp = -HUGE_VAL;
};

inline Loudness loudness(const std::vector<float>& stereo) {
    ebur128_state* st = ebur128_init(2, kRate, EBUR128_MODE_I | EBUR128_MODE_TRUE_PEAK);
    ebur128_add_frames_float(st, stereo.data(), stereo.size() / 2);
    Loudness l;
    ebur128_loudness_global(st, &l.integrated_lufs);
    double peak = 0.0;
    for (unsigned c = 0; c < 2; ++c) {
        double p = 0.0;
        ebur128_true_peak(st, c, &p);
        peak = std::max(peak, p);
    }
    l.true_peak_dbtp = peak > 0.0 ? 20.0 * std::log10(peak) : -HUGE_VAL;
    ebur128_destroy(&st);
    return l;
}

// The first sample that is NaN, infinite, subnormal or at/over full scale, if any.
inline std::optional<size_t> bad_sample(const std::vector<float>& s) {
    for (size_t i = 0; i < s.size(); ++i) {
        const float x = s[i];
        if (!std::isfinite(x) || (x != 0.0f && std::fpclassify(x) == FP_SUBNORMAL) || std::fabs(x) >= 1.0f) return i;
    }
    return std::nullopt;
}

inline std::vector<float> mono(const std::vector<float>& stereo) {
    std::vector<float> m(stereo.size() / 2);
    for (size_t i = 0; i < m.size(); ++i) m[i] = 0.5f * (stereo[2 * i] + stereo[2 * i + 1]);
    return m;
}

// A fourth-order Butterworth high-pass or low-pass (two cascaded RBJ sections at Q 0.541 and 1.307).
inline std::vector<float> butterworth(const std::vector<float>& x, double hz, bool high) {
    std::vector<float> y(x.begin(), x.end());
    for (double q : {0.5412, 1.3066}) {
        const double w = 2.0 * M_PI * hz / kRate, c = std::cos(w), a = std::sin(w) / (2.0 * q);
        const double sign = high ? 1.0 : -1.0;  // (1 + c) for the high-pass, (1 - c) for the low-pass
        const double b0 = (1 + sign * c) / 2 / (1 + a), b1 = -sign * (1 + sign * c) / (1 + a), b2 = b0,
                     a1 = -2 * c / (1 + a), a2 = (1 - a) / (1 + a);
        double x1 = 0, x2 = 0, y1 = 0, y2 = 0;
        for (float& v : y) {
            const double in = v, out = b0 * in + b1 * x1 + b2 * x2 - a1 * y1 - a2 * y2;
            x2 = x1, x1 = in, y2 = y1, y1 = out;
            v = float(out);
        }
    }
    return y;
}

inline std::vector<float> highpass(const std::vector<float>& x, double hz) { return butterworth(x, hz, true); }
inline std::vector<float> lowpass(const std::vector<float>& x, double hz) { return butterworth(x, hz, false); }
inline std::vector<float> bandpass(const std::vector<float>& x, double lo_hz, double hi_hz) {
    return lowpass(highpass(x, lo_hz), hi_hz);
}

// Mean square of samples [from, to).
inline double power(const std::vector<float>& x, size_t from, size_t to) {
    to = std::min(to, x.size());
    if (to <= from) return 0.0;
    double s = 0.0;
    for (size_t i = from; i < to; ++i) s += double(x[i]) * x[i];
    return s / double(to - from);
}

inline double db(double p) { return 10.0 * std::log10(p + 1e-30); }

// Whether an onset falls within one tick of `tick`'s first sample (tick t is rendered
// from sample (t-1) * 800): a 2.5 ms frame whose power rises `rise_db` over the mean
// of the 25 ms before it.
inline bool onset_near(const std::vector<float>& m, uint64_t tick, double rise_db = 4.0) {
    constexpr size_t kFrame = 120, kBefore = 1200;
    const long centre = long(tick - 1) * kTickFrames;
    for (long at = centre - kTickFrames; at <= centre + kTickFrames; at += long(kFrame / 2)) {
        if (at < long(kBefore)) continue;
        const size_t a = size_t(at);
        const double now = power(m, a, a + kFrame), before = power(m, a - kBefore, a);
        if (now > 1e-9 && db(now) - db(before) >= rise_db) return true;
    }
    return false;
}

// The strongest periodicity between lo_hz and hi_hz of a window, by normalised
// autocorrelation (the first lag whose correlation is within 10% of the best, so a
// sub-harmonic does not win).
inline double pitch_hz(const std::vector<float>& x, int rate, size_t from, size_t length, double lo_hz, double hi_hz) {
    const size_t min_lag = size_t(rate / hi_hz), max_lag = size_t(rate / lo_hz);
    if (from + length + max_lag > x.size()) return 0.0;
    std::vector<double> r(max_lag + 1, 0.0);
    double best = 0.0;
    for (size_t lag = min_lag; lag <= max_lag; ++lag) {
        double s = 0.0, e0 = 0.0, e1 = 0.0;
        for (size_t i = from; i < from + length; ++i) {
            s += double(x[i]) * x[i + lag];
            e0 += double(x[i]) * x[i];
            e1 += double(x[i + lag]) * x[i + lag];
        }
        r[lag] = s / std::sqrt(e0 * e1 + 1e-30);
        best = std::max(best, r[lag]);
    }
    if (best < 0.3) return 0.0;
    for (size_t lag = min_lag + 1; lag < max_lag; ++lag)
        if (r[lag] >= 0.9 * best && r[lag] >= r[lag - 1] && r[lag] >= r[lag + 1]) return double(rate) / double(lag);
    return 0.0;
}

// Every `factor` samples averaged into one: a crude low-pass and decimation, enough
// for a pitch track far below the new Nyquist frequency.
inline std::vector<float> decimate(const std::vector<float>& x, size_t factor) {
    std::vector<float> y(x.size() / factor);
    for (size_t i = 0; i < y.size(); ++i) {
        double s = 0.0;
        for (size_t k = 0; k < factor; ++k) s += x[i * factor + k];
        y[i] = float(s / double(factor));
    }
    return y;
}

// Spearman's rank correlation of two equally long series.
inline double rank_correlation(const std::vector<double>& a, const std::vector<double>& b) {
    auto ranks = [](const std::vector<double>& v) {
        std::vector<size_t> order(v.size());
        for (size_t i = 0; i < v.size(); ++i) order[i] = i;
        std::sort(order.begin(), order.end(), [&](size_t i, size_t j) { return v[i] < v[j]; });
        std::vector<double> r(v.size());
        for (size_t i = 0; i < order.size(); ++i) r[order[i]] = double(i);
        return r;
    };
    const std::vector<double> ra = ranks(a), rb = ranks(b);
    const double n = double(a.size()), mean = (n - 1.0) / 2.0;
    double num = 0.0, da = 0.0, db2 = 0.0;
    for (size_t i = 0; i < a.size(); ++i) {
        num += (ra[i] - mean) * (rb[i] - mean);
        da += (ra[i] - mean) * (ra[i] - mean);
        db2 += (rb[i] - mean) * (rb[i] - mean);
    }
    return num / std::sqrt(da * db2 + 1e-30);
}

}  // namespace audio_test
