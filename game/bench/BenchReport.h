#pragma once
// Benchmark results: printed as a table and written as JSON, each case with its
// target (and the baseline it is compared with, where there is one).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace game {

struct BenchCase {
    std::string group;  // "sim", "replay", "render", "memory", or an effect's name
    std::string name;
    double value = 0.0;
    std::string unit;                 // "ms", "x realtime", "MiB"
    std::optional<double> target;     // the value must stay at or below (or above, see higher_is_better)
    bool higher_is_better = false;
    std::string note;
    bool meets_target() const {
        if (!target) return true;
        return higher_is_better ? value >= *target : value <= *target;
    }
};

class BenchReport {
public:
    void add(BenchCase c) { cases_.push_back(std::move(c)); }
    const std::vector<BenchCase>& cases() const { return cases_; }
    void print_table() const;
    void write_json(const std::filesystem::path& path, const std::string& renderer) const;

private:
    std::vector<BenchCase> cases_;
};

}  // namespace game
