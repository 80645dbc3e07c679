#include "game/replay/ViewerTransport.h"

#include <algorithm>
#include <cmath>

#include "sim/world/World.h"

namespace game {

void ViewerTransport::toggle_pause() {
    // Play again from the end: from the start.
    if (paused_ && seeker_.tick() >= seeker_.ticks()) go_to(0);
    paused_ = !paused_;
    owed_ = 0.0;
}

void ViewerTransport::faster() { speed_index_ = std::min(speed_index_ + 1, kSpeeds.size() - 1); }
void ViewerTransport::slower() { speed_index_ = speed_index_ > 0 ? speed_index_ - 1 : 0; }

void ViewerTransport::go_to(uint64_t tick) {
    paused_ = true;
    owed_ = 0.0;
    const uint64_t before = seeker_.tick();
    seeker_.seek(tick);
    jumped_ = seeker_.tick() != before + 1;
}

void ViewerTransport::step_forward() { go_to(seeker_.tick() + 1); }
void ViewerTransport::step_back() { go_to(seeker_.tick() > 0 ? seeker_.tick() - 1 : 0); }
void ViewerTransport::seek_to(uint64_t tick) { go_to(tick); }

void ViewerTransport::jump_seconds(double seconds) {
    const double to = double(seeker_.tick()) + seconds * sim::kTickRateHz;
    go_to(uint64_t(std::clamp(std::llround(to), 0ll, (long long)seeker_.ticks())));
}

void ViewerTransport::next_marker() {
    if (auto m = markers_.next_after(seeker_.tick())) go_to(m->tick);
}

void ViewerTransport::previous_marker() {
    if (auto m = markers_.previous_before(seeker_.tick())) go_to(m->tick);
}

int ViewerTransport::ticks_due(double dt_s) {
    jumped_ = false;
    if (paused_) return 0;
    owed_ += std::max(0.0, dt_s) * speed() * sim::kTickRateHz;
    int n = std::min(int(std::floor(owed_)), kMaxTicksPerFrame);
    owed_ = std::min(owed_ - n, 1.0 - 1e-9);
    n = int(std::min<uint64_t>(uint64_t(n), seeker_.ticks() - std::min(seeker_.tick(), seeker_.ticks())));
    if (seeker_.tick() + uint64_t(n) >= seeker_.ticks()) {
        paused_ = true;
        owed_ = 0.0;
    }
    return n;
}

int ViewerTransport::advance(double dt_s) {
    const int n = ticks_due(dt_s);
    for (int i = 0; i < n; ++i) seeker_.step();
    return n;
}

}  // namespace game
