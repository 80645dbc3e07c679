// The mixer's placement with a test tone: panning, distance, Doppler from motion but
// not from a cut, the cabin's walls, mute.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "AudioAnalysis.h"
#include "audio/Mixer.h"

namespace {

using namespace audio_test;

// A steady sine whose frequency follows the pitch factor the mixer passes.
class Tone final : public audio::Voice {
public:
    explicit Tone(float hz) : Voice(audio::Bus::Effects), hz_(hz) {}
    bool render(float* out, int frames, float pitch) override {
        for (int n = 0; n < frames; ++n) {
            out[n] += 0.2f * std::sin(float(2.0 * M_PI) * phase_);
            phase_ += hz_ * pitch / float(kRate);
            if (phase_ >= 1.0f) phase_ -= 1.0f;
        }
        return true;
    }

private:
    float hz_;
    float phase_ = 0.0f;
};

struct Heard {
    double left = 0.0, right = 0.0;  // mean square
    double hz = 0.0;                 // from the left channel's zero crossings
};

// Places the tone at `position(tick)` for `ticks` ticks, the listener at the origin
// looking down -z, and measures the last half second.
template <class Where>
Heard listen(Where position, int ticks, bool in_cabin = false, float hz = 440.0f) {
    audio::Mixer mixer;
    Tone tone(hz);
    tone.place.positioned = true;
    tone.place.reference_m = 2.0f;
    mixer.add(tone);
    audio::Listener listener;
    listener.in_cabin = in_cabin;
    std::vector<float> all, block(2 * kTickFrames);
    for (int t = 0; t < ticks; ++t) {
        tone.place.position = position(t);
        mixer.update_placement(listener, 1.0f / 60.0f);
        mixer.render(block.data(), kTickFrames);
        all.insert(all.end(), block.begin(), block.end());
    }
    Heard h;
    const size_t from = all.size() / 2 - size_t(kRate / 2);
    std::vector<float> left, right;
    for (size_t i = from; i < all.size() / 2; ++i) {
        left.push_back(all[2 * i]);
        right.push_back(all[2 * i + 1]);
    }
    h.left = power(left, 0, left.size());
    h.right = power(right, 0, right.size());
    int crossings = 0;
    for (size_t i = 1; i < left.size(); ++i) crossings += (left[i - 1] < 0.0f) != (left[i] < 0.0f);
    h.hz = crossings / 2.0 / (double(left.size()) / kRate);
    return h;
}

TEST(Mixer, ASourceOnTheRightIsLouderOnTheRight) {
    const Heard h = listen([](int) { return glm::vec3(5.0f, 0.0f, 0.0f); }, 60);
    EXPECT_GT(db(h.right) - db(h.left), 12.0);
    const Heard ahead = listen([](int) { return glm::vec3(0.0f, 0.0f, -5.0f); }, 60);
    EXPECT_NEAR(db(ahead.right), db(ahead.left), 0.1);
}

TEST(Mixer, TwiceAsFarIsSixDecibelsQuieter) {
    const Heard near = listen([](int) { return glm::vec3(0.0f, 0.0f, -8.0f); }, 60);
    const Heard far = listen([](int) { return glm::vec3(0.0f, 0.0f, -16.0f); }, 60);
    EXPECT_NEAR(db(near.left) - db(far.left), 6.02, 0.2);
}

TEST(Mixer, AnApproachingSourceIsHigherAndACutChangesNothing) {
    // Closing at 20 m/s: c / (c - v) = 343 / 323.
    const Heard moving = listen([](int t) { return glm::vec3(0.0f, 0.0f, -200.0f + 20.0f * float(t) / 60.0f); }, 120);
    EXPECT_NEAR(moving.hz / 440.0, 343.0 / 323.0, 0.01);
    // A jump of 100 m in a tick is a cut: the pitch stays.
    const Heard cut = listen([](int t) { return glm::vec3(0.0f, 0.0f, t < 60 ? -150.0f : -50.0f); }, 120);
    EXPECT_NEAR(cut.hz, 440.0, 3.0);
}

TEST(Mixer, TheCabinsWallsMuffleHighs) {
    const Heard open = listen([](int) { return glm::vec3(0.0f, 0.0f, -5.0f); }, 60, false, 4000.0f);
    const Heard walled = listen([](int) { return glm::vec3(0.0f, 0.0f, -5.0f); }, 60, true, 4000.0f);
    EXPECT_LT(db(walled.left), db(open.left) - 20.0);
}

TEST(Mixer, MutedIsSilent) {
    audio::Mixer mixer;
    Tone tone(440.0f);
    mixer.add(tone);
    mixer.update_placement({}, 1.0f / 60.0f);
    mixer.set_muted(true);
    std::vector<float> block(2 * 512);
    for (int i = 0; i < 40; ++i) mixer.render(block.data(), 512);
    EXPECT_LT(power(block, 0, block.size()), 1e-12);
}

}  // namespace
