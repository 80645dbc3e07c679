// The hand-off between the game and the mixing thread: the game updates at 10 frames a
// second (six ticks at once, then a stall of a frame's length), the mixing thread keeps
// rendering blocks through every stall without waiting, and what it renders is
// continuous: the changes land at block boundaries and are smoothed across the block.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

#include "AudioAnalysis.h"
#include "audio/Mixer.h"

namespace {

using namespace audio_test;

constexpr int kBlock = 512;
constexpr float kLoudest = 0.25f, kHighest_hz = 520.0f;

// A sine whose level and frequency are set once a tick and smoothed within each block,
// as the sound models' parameters are.
class Tone final : public audio::Voice {
public:
    Tone() : Voice(audio::Bus::Effects) {}
    void set(float level, float hz) {
        level_.set(level);
        hz_.set(hz);
    }
    bool render(float* out, int frames, float pitch) override {
        level_.begin_block(frames);
        hz_.begin_block(frames);
        for (int n = 0; n < frames; ++n) {
            const float level = level_.next();
            phase_ += hz_.next() * pitch / float(kRate);
            if (phase_ >= 1.0f) phase_ -= 1.0f;
            out[n] += level * std::sin(float(2.0 * M_PI) * phase_);
        }
        return true;
    }
    float level_target() const { return level_.target(); }

private:
    audio::Smoothed level_{0.0f, 0.03f}, hz_{300.0f, 0.04f};
    float phase_ = 0.0f;
};

// The mixing side as a live output runs it: blocks, one after another, on its own thread.
struct MixingThread {
    audio::Mixer& mixer;
    std::vector<float> out;
    std::atomic<int> blocks{0};
    std::atomic<bool> stop{false};
    std::mutex m;  // only for the test's wait on the thread's progress, never taken by the mix
    std::condition_variable progressed;
    std::thread thread;

    explicit MixingThread(audio::Mixer& mix) : mixer(mix) {
        out.reserve(size_t(2 * kBlock * 4000));
        thread = std::thread([this] {
            std::vector<float> block(2 * kBlock);
            while (!stop) {
                mixer.render(block.data(), kBlock);
                out.insert(out.end(), block.begin(), block.end());
                ++blocks;
                progressed.notify_all();
                std::this_thread::sleep_for(std::chrono::microseconds(500));  // a device's pace, roughly
            }
        });
    }
    // Waits until `n` blocks have been rendered; false if the thread did not get there
    // (it would be waiting for the game), after a generous guard against a hang.
    bool reaches(int n) {
        std::unique_lock lock(m);
        return progressed.wait_for(lock, std::chrono::seconds(30), [&] { return blocks >= n; });
    }
    void finish() {
        stop = true;
        thread.join();
    }
};

TEST(MixerHandOff, AtTenFramesASecondTheMixNeverWaitsAndStaysContinuous) {
    audio::Mixer mixer;
    Tone tone;
    tone.place.positioned = true;
    tone.place.reference_m = 2.0f;
    tone.place.position = glm::vec3(0.0f, 0.0f, -2.0f);
    audio::MixChanges start;
    start.add(tone);
    start.update_placement({}, 1.0f / 60.0f);
    mixer.submit(std::move(start));

    MixingThread mixing(mixer);
    int underruns = 0, tick = 0;
    for (int frame = 0; frame < 30; ++frame) {
        // One frame's six ticks at once, each changing the level, pitch and side abruptly.
        for (int t = 0; t < 6; ++t, ++tick) {
            audio::MixChanges changes;
            const bool odd = tick % 2 == 1;
            const float level = odd ? kLoudest : 0.05f, hz = odd ? kHighest_hz : 300.0f;
            const glm::vec3 where(odd ? 3.0f : -3.0f, 0.0f, -2.0f);
            changes.then([&tone, level, hz, where](audio::Mixer&) {
                tone.set(level, hz);
                tone.place.position = where;
            });
            changes.update_placement({}, 1.0f / 60.0f);
            mixer.submit(std::move(changes));
        }
        // The frame stalls for 100 ms of sound: the device keeps asking for blocks, and
        // each one it had to wait for the game for would be a block run dry.
        const int due = mixing.blocks + int(0.1 * kRate / kBlock) + 1;
        if (!mixing.reaches(due)) ++underruns;
    }
    mixing.finish();
    EXPECT_EQ(underruns, 0);
    EXPECT_EQ(mixer.pending(), 0u) << "every change was taken";
    EXPECT_FLOAT_EQ(tone.level_target(), kLoudest) << "the last tick's change was applied";

    // Continuous: no sample steps further than the loudest, highest tone can move in one
    // sample (its slope, 2 pi f A / rate, after the mix's level), with 50% to spare. A
    // change applied at a block boundary without smoothing would step many times that.
    const std::vector<float>& out = mixing.out;
    ASSERT_GT(out.size(), size_t(2 * kRate));
    const double slope = 2.0 * M_PI * kHighest_hz * kLoudest / kRate * 0.4;  // 0.4: the mixer's level
    double worst = 0.0;
    size_t worst_at = 0;
    for (size_t i = 2; i < out.size(); ++i) {
        const double step = std::fabs(double(out[i]) - out[i - 2]);  // the same channel
        if (step > worst) worst = step, worst_at = i / 2;
    }
    EXPECT_LT(worst, 1.5 * slope) << "at frame " << worst_at << " (block " << worst_at / kBlock << ", "
                                  << worst_at % kBlock << " into it)";
    EXPECT_GT(power(out, 0, out.size()), 1e-6) << "the tone was heard";
}

}  // namespace
