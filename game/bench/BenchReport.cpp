#include "game/bench/BenchReport.h"

#include <cstdio>
#include <span>

#include <nlohmann/json.hpp>

#include "game/capture/ImageFiles.h"

namespace game {

void BenchReport::print_table() const {
    std::printf("%-8s %-44s %12s %-12s %s\n", "group", "case", "value", "unit", "target");
    for (const BenchCase& c : cases_) {
        std::string target = "-";
        if (c.target) {
            char buf[64];
            std::snprintf(buf, sizeof buf, "%s %.3g %s", c.higher_is_better ? ">=" : "<=", *c.target,
                          c.meets_target() ? "ok" : "MISSED");
            target = buf;
        }
        std::printf("%-8s %-44s %12.3f %-12s %s%s%s\n", c.group.c_str(), c.name.c_str(), c.value, c.unit.c_str(),
                    target.c_str(), c.note.empty() ? "" : "  ", c.note.c_str());
    }
}

void BenchReport::write_json(const std::filesystem::path& path, const std::string& renderer) const {
    nlohmann::json j;
    j["renderer"] = renderer;
    j["cases"] = nlohmann::json::array();
    for (const BenchCase& c : cases_) {
        nlohmann::json e{{"group", c.group}, {"name", c.name}, {"value", c.value}, {"unit", c.unit},
                         {"meets_target", c.meets_target()}};
        if (c.target) {
            e["target"] = *c.target;
            e["higher_is_better"] = c.higher_is_better;
        }
        if (!c.note.empty()) e["note"] = c.note;
        j["cases"].push_back(e);
    }
    const std::string text = j.dump(2) + "\n";
    write_file_atomically(path, std::span(reinterpret_cast<const unsigned char*>(text.data()), text.size()));
}

}  // namespace game
