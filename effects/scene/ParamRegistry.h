#pragma once
// Live-tweakable parameters that passes register; the game's debug panel shows them.
#include <string>
#include <vector>

namespace effects {

struct Param {
    enum class Kind { Float, Int, Bool };
    std::string group;  // the pass's name
    std::string name;
    Kind kind = Kind::Float;
    void* value = nullptr;  // float*, int* or bool*, owned by the pass
    float min = 0.0f, max = 1.0f;
};

class ParamRegistry {
public:
    void add(std::string group, std::string name, float* v, float min, float max) {
        params_.push_back({std::move(group), std::move(name), Param::Kind::Float, v, min, max});
    }
    void add(std::string group, std::string name, int* v, int min, int max) {
        params_.push_back({std::move(group), std::move(name), Param::Kind::Int, v, float(min), float(max)});
    }
    void add(std::string group, std::string name, bool* v) {
        params_.push_back({std::move(group), std::move(name), Param::Kind::Bool, v, 0.0f, 1.0f});
    }
    const std::vector<Param>& params() const { return params_; }

private:
    std::vector<Param> params_;
};

}  // namespace effects
