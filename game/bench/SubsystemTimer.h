#pragma once
// Times each subsystem's step with the wall clock, from outside the sim.
#include <chrono>
#include <vector>

#include "sim/world/World.h"

namespace game {

class SubsystemTimer final : public sim::StepObserver {
public:
    explicit SubsystemTimer(size_t subsystems) : total_s_(subsystems, 0.0) {}
    void before(size_t) override { start_ = std::chrono::steady_clock::now(); }
    void after(size_t i) override {
        total_s_[i] += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }
    const std::vector<double>& total_seconds() const { return total_s_; }

private:
    std::chrono::steady_clock::time_point start_;
    std::vector<double> total_s_;
};

}  // namespace game
