#include "game/replay/KeyframeStore.h"

#include <stdexcept>
#include <string>

#include <zstd.h>

#include "sim/core/StateArchive.h"

namespace game {

KeyframeStore::KeyframeStore(uint64_t level_hash, uint32_t interval_ticks, int level)
    : level_hash_(level_hash), interval_(interval_ticks), level_(level) {
    if (interval_ticks == 0) throw std::invalid_argument("keyframes: the interval must be at least one tick");
}

void KeyframeStore::offer(const sim::World& world) {
    const uint64_t tick = world.tick();
    if (tick % interval_ != 0 || frames_.count(tick)) return;
    const std::vector<uint8_t> raw = world.snapshot(level_hash_);
    std::vector<uint8_t> packed(ZSTD_compressBound(raw.size()));
    const size_t n = ZSTD_compress(packed.data(), packed.size(), raw.data(), raw.size(), level_);
    if (ZSTD_isError(n)) throw std::runtime_error(std::string("keyframes: zstd: ") + ZSTD_getErrorName(n));
    packed.resize(n);
    packed.shrink_to_fit();
    compressed_ += n;
    raw_ += raw.size();
    frames_.emplace(tick, std::move(packed));
}

std::optional<uint64_t> KeyframeStore::at_or_before(uint64_t tick) const {
    auto it = frames_.upper_bound(tick);
    if (it == frames_.begin()) return std::nullopt;
    return std::prev(it)->first;
}

void KeyframeStore::restore(uint64_t tick, sim::World& world) const {
    auto it = frames_.find(tick);
    if (it == frames_.end()) throw std::logic_error("keyframes: none at tick " + std::to_string(tick));
    const std::vector<uint8_t>& packed = it->second;
    const unsigned long long size = ZSTD_getFrameContentSize(packed.data(), packed.size());
    if (size == ZSTD_CONTENTSIZE_ERROR || size == ZSTD_CONTENTSIZE_UNKNOWN)
        throw sim::SnapshotError("keyframe of tick " + std::to_string(tick) + ": not a zstd frame with its size");
    scratch_.resize(size_t(size));
    const size_t n = ZSTD_decompress(scratch_.data(), scratch_.size(), packed.data(), packed.size());
    if (ZSTD_isError(n) || n != size)
        throw sim::SnapshotError("keyframe of tick " + std::to_string(tick) + ": " +
                                 (ZSTD_isError(n) ? ZSTD_getErrorName(n) : "short"));
    world.restore(scratch_, level_hash_);
}

}  // namespace game
