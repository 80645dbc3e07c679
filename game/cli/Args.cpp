#include "game/cli/Args.h"

#include <charconv>

namespace game {

Args::Args(const std::vector<std::string>& argv, const std::set<std::string>& with_value,
           const std::set<std::string>& flags) {
    for (size_t i = 0; i < argv.size(); ++i) {
        const std::string& a = argv[i];
        if (a.rfind("--", 0) != 0 || a == "--") {
            positional_.push_back(a);
            continue;
        }
        std::string name = a, val;
        bool inline_value = false;
        if (auto eq = a.find('='); eq != std::string::npos) {
            name = a.substr(0, eq);
            val = a.substr(eq + 1);
            inline_value = true;
        }
        if (with_value.count(name)) {
            if (!inline_value) {
                if (i + 1 >= argv.size()) throw UsageError(name + " needs a value");
                val = argv[++i];
            }
            if (values_.count(name)) throw UsageError(name + " given twice");
            values_[name] = val;
        } else if (flags.count(name)) {
            if (inline_value) throw UsageError(name + " takes no value");
            flags_.insert(name);
        } else {
            throw UsageError("unknown option " + name);
        }
    }
}

std::optional<std::string> Args::value(const std::string& name) const {
    auto it = values_.find(name);
    if (it == values_.end()) return std::nullopt;
    return it->second;
}

int Args::integer(const std::string& name, int fallback, int lo, int hi) const {
    auto v = value(name);
    if (!v) return fallback;
    int out = 0;
    auto [end, ec] = std::from_chars(v->data(), v->data() + v->size(), out);
    if (ec != std::errc() || end != v->data() + v->size() || out < lo || out > hi)
        throw UsageError(name + " must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) +
                         ", got '" + *v + "'");
    return out;
}

}  // namespace game
