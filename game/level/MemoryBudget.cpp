#include "game/level/MemoryBudget.h"

#include <algorithm>
#include <cstdio>
#include <utility>

namespace game {

std::string show_mib(uint64_t bytes) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f MiB", double(bytes) / double(kMiB));
    return buf;
}

MemoryBudget::MemoryBudget(std::string owner, uint64_t budget_bytes)
    : owner_(std::move(owner)), budget_bytes_(budget_bytes) {}

void MemoryBudget::charge(std::string name, uint64_t bytes) {
    if (!fits(bytes)) refuse({name, bytes});
    used_bytes_ += bytes;
    terms_.push_back({std::move(name), bytes});
}

void MemoryBudget::require(const std::string& name, uint64_t bytes) const {
    if (!fits(bytes)) refuse({name, bytes});
}

void MemoryBudget::refuse(const MemoryTerm& extra) const {
    // Name the largest terms: they are what to shrink (or what the budget must cover).
    std::vector<MemoryTerm> largest = terms_;
    largest.push_back(extra);
    std::stable_sort(largest.begin(), largest.end(),
                     [](const MemoryTerm& a, const MemoryTerm& b) { return a.bytes > b.bytes; });
    std::string list;
    for (size_t i = 0; i < largest.size() && i < 4; ++i)
        list += (i ? ", " : "") + largest[i].name + " " + show_mib(largest[i].bytes);
    const uint64_t needed = used_bytes_ + std::min(extra.bytes, UINT64_MAX - used_bytes_);
    throw LevelError(owner_ + ": budget_mib: the level needs at least " + show_mib(needed) + " (" + list +
                     "), more than its budget of " + show_mib(budget_bytes_));
}

}  // namespace game
