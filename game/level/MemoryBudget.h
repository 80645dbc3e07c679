#pragma once
// A level's memory budget ("budget_mib" in its JSON) and the estimated terms charged
// against it. Each term is charged from sizes the level states, before the allocation it
// stands for; the first that does not fit throws LevelError naming the budget and the
// largest terms, so an absurd level is refused before it can take the memory.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "game/level/LevelError.h"

namespace game {

inline constexpr uint64_t kMiB = uint64_t(1) << 20;
inline constexpr uint64_t kMinLevelBudgetMib = 64;
inline constexpr uint64_t kMaxLevelBudgetMib = 64 * 1024;
inline constexpr uint64_t kDefaultLevelBudgetMib = 1024;  // a level without budget_mib

struct MemoryTerm {
    std::string name;  // what it is for, with the sizes it comes from: "wave grid 256x256"
    uint64_t bytes = 0;
};

class MemoryBudget {
public:
    // `owner` starts every message: the level file.
    MemoryBudget(std::string owner, uint64_t budget_bytes);
    MemoryBudget() : MemoryBudget("", kDefaultLevelBudgetMib * kMiB) {}

    // Adds a term; throws LevelError if the total would pass the budget.
    void charge(std::string name, uint64_t bytes);
    // A passing need (a file being parsed): throws like charge() if it does not fit now,
    // but keeps nothing.
    void require(const std::string& name, uint64_t bytes) const;
    // Whether `bytes` more would still fit.
    bool fits(uint64_t bytes) const { return bytes <= budget_bytes_ - used_bytes_; }

    uint64_t budget_bytes() const { return budget_bytes_; }
    uint64_t used_bytes() const { return used_bytes_; }
    const std::vector<MemoryTerm>& terms() const { return terms_; }

private:
    [[noreturn]] void refuse(const MemoryTerm& extra) const;

    std::string owner_;
    uint64_t budget_bytes_ = 0;
    uint64_t used_bytes_ = 0;
    std::vector<MemoryTerm> terms_;
};

// "12.5 MiB": a size for messages.
std::string show_mib(uint64_t bytes);

}  // namespace game
