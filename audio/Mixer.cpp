#include "audio/Mixer.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace audio {

namespace {
constexpr int kBlock = 512;
constexpr float kSpeedOfSound = 343.0f;
constexpr float kWallCutoffHz = 650.0f;  // a car's body passes little above this
constexpr float kWallGain = 0.5f;
// Full scale is never reached: above the knee the signal bends towards the ceiling.
constexpr float kKnee = 0.5f, kCeiling = 0.8f;
// The mix's level: the bundled replays' integrated loudness near -23 LUFS (EBU R 128).
constexpr float kMixLevel = 0.4f;

float soft_ceiling(float x) {
    const float a = std::fabs(x);
    if (a <= kKnee) return x;
    const float room = kCeiling - kKnee;
    const float bent = kKnee + room * std::tanh((a - kKnee) / room);
    return x < 0.0f ? -bent : bent;
}
}  // namespace

Mixer::Mixer() {
    for (Smoothed& s : bus_gain_) s = Smoothed(1.0f, 0.05f);
    scratch_.resize(kBlock);
}

void Mixer::submit(MixChanges changes) {
    // enqueue (not try_enqueue): a full queue grows on this side rather than dropping a change.
    if (!changes.empty()) inbox_.enqueue(std::move(changes));
}

void Mixer::apply_changes() {
    MixChanges changes;
    while (inbox_.try_dequeue(changes)) changes.apply(*this);
}

void Mixer::add(Voice& voice) {
    Channel c;
    c.voice = &voice;
    c.wall.set_cutoff(kWallCutoffHz);
    channels_.push_back(std::move(c));
}

void Mixer::remove(Voice& voice) {
    std::erase_if(channels_, [&](const Channel& c) { return c.voice == &voice; });
}

void Mixer::play(std::unique_ptr<Voice> voice) {
    Channel c;
    c.voice = voice.get();
    c.owned = std::move(voice);
    c.wall.set_cutoff(kWallCutoffHz);
    place_channel(c, listener_, 0.0f);
    channels_.push_back(std::move(c));
}

int Mixer::live_voices() const {
    int n = 0;
    for (const Channel& c : channels_) n += c.voice->audible() ? 1 : 0;
    return n;
}

void Mixer::update_placement(const Listener& listener, float tick_s) {
    listener_ = listener;
    for (Channel& c : channels_) place_channel(c, listener, tick_s);
}

void Mixer::place_channel(Channel& c, const Listener& l, float tick_s) {
    const Placement& p = c.voice->place;
    float left = 0.7071f, right = 0.7071f;
    if (p.positioned) {
        const glm::vec3 to = p.position - l.position;
        const float d = std::sqrt(glm::dot(to, to));
        const float gain = std::min(1.0f, p.reference_m / std::max(d, 1e-3f));
        glm::vec3 side = glm::cross(l.forward, l.up);
        const float side_len = std::sqrt(glm::dot(side, side));
        float x = 0.0f, behind = 1.0f;
        if (d > 1e-3f && side_len > 1e-6f) {
            // Close by, a source is in the middle of the head rather than flipping sides.
            const float spread = std::min(1.0f, d / 1.5f);
            x = spread * glm::dot(to, side) / (d * side_len);
            if (glm::dot(to, l.forward) < 0.0f) behind = 0.85f;
        }
        const float angle = (x + 1.0f) * (kPi * 0.25f);
        left = gain * behind * std::cos(angle);
        right = gain * behind * std::sin(angle);
        // Doppler from the rate the distance shrinks, smoothed over about 0.1 s of sim
        // time: a camera's jitter or a cut does not make the pitch wobble or jump.
        if (c.distance_m >= 0.0f && tick_s > 0.0f) {
            float closing = (c.distance_m - d) / tick_s;
            if (std::fabs(closing) > 60.0f) closing = 0.0f;  // a cut, not a motion
            c.closing_mps += (closing - c.closing_mps) * 0.15f;
        }
        c.distance_m = d;
        const float shift = std::clamp(kSpeedOfSound / (kSpeedOfSound - c.closing_mps * p.doppler), 0.8f, 1.25f);
        c.pitch.set(shift);
    }
    c.left.set(left);
    c.right.set(right);
    c.muffle.set(l.in_cabin && p.outside ? 1.0f : 0.0f);
    if (!c.placed) {  // a new voice starts where it is, without sweeping in
        c.left.jump(left);
        c.right.jump(right);
        c.pitch.jump(c.pitch.target());
        c.muffle.jump(c.muffle.target());
        c.placed = true;
    }
}

void Mixer::render(float* out, int frames) {
    apply_changes();
    for (int done = 0; done < frames;) {
        const int n = std::min(kBlock, frames - done);
        render_block(out + 2 * done, n);
        done += n;
    }
}

void Mixer::render_block(float* out, int frames) {
    std::fill(out, out + 2 * frames, 0.0f);
    if (silent()) return;
    const std::array<float, kBusCount> bus_target{volumes_.engine, volumes_.effects, volumes_.ambience};
    for (int b = 0; b < kBusCount; ++b) {
        bus_gain_[size_t(b)].set(bus_target[size_t(b)]);
        bus_gain_[size_t(b)].begin_block(frames);
    }
    for (size_t i = 0; i < channels_.size();) {
        Channel& c = channels_[i];
        c.left.begin_block(frames);
        c.right.begin_block(frames);
        c.pitch.begin_block(frames);
        c.muffle.begin_block(frames);
        if (!c.voice->audible() && c.owned == nullptr) {
            ++i;
            continue;
        }
        std::fill(scratch_.begin(), scratch_.begin() + frames, 0.0f);
        const bool alive = c.voice->render(scratch_.data(), frames, c.pitch.value());
        // Bus gains move slowly (50 ms): their block value is close enough per sample.
        const float bus = bus_gain_[size_t(int(c.voice->bus()))].value();
        for (int k = 0; k < frames; ++k) {
            float x = scratch_[size_t(k)];
            // The wall's filter always runs, so stepping into the cabin does not click.
            const float walled = c.wall.lowpass(x) * kWallGain;
            x = (x + (walled - x) * c.muffle.next()) * bus;
            out[2 * k] += x * c.left.next();
            out[2 * k + 1] += x * c.right.next();
        }
        if (!alive && c.owned) {
            channels_.erase(channels_.begin() + long(i));
            continue;
        }
        ++i;
    }
    master_.set(muted_ || paused_ ? 0.0f : volumes_.master);
    master_.begin_block(frames);
    for (int k = 0; k < frames; ++k) {
        const float g = master_.next() * kMixLevel;
        out[2 * k] = soft_ceiling(out[2 * k] * g);
        out[2 * k + 1] = soft_ceiling(out[2 * k + 1] * g);
    }
    // Nothing subnormal leaves the mixer (a decaying filter tail would be one).
    for (int k = 0; k < 2 * frames; ++k)
        if (std::fabs(out[k]) < 1e-20f) out[k] = 0.0f;
}

}  // namespace audio
