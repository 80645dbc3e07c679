// The level loader refuses broken courses and targets, naming the entry.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "LevelFiles.h"

using namespace level_files;

// Courses and targets: the harbour has a car course (courses[0]) and a boat course
// (courses[1]); broken ones are refused naming the entry.
TEST(LevelObjectives, BrokenCoursesAndTargetsAreNamed) {
    const json harbour = json::parse(slurp(harbour_json()));
    ASSERT_GE(harbour.at("courses").size(), 2u);
    ASSERT_EQ(harbour["courses"][0]["vehicle"], "car");
    ASSERT_EQ(harbour["courses"][1]["vehicle"], "boat");
    ASSERT_GE(harbour.at("targets").size(), 1u);
    expect_each_refused("objectives", harbour, {
        {[](json& j) { j["courses"][0]["gates"] = json::array({j["courses"][0]["gates"][0]}); },
         {"courses[0].gates: a course needs at least 2 gates, found 1"}},
        {[](json& j) { j["courses"][0]["vehicle"] = "bike"; }, {"courses[0].vehicle: expected \"car\" or \"boat\", got \"bike\""}},
        {[](json& j) { j["courses"][1]["name"] = j["courses"][0]["name"]; }, {"courses[1].name:", "names another course too"}},
        {[](json& j) { j["courses"][0]["name"] = ""; }, {"courses[0].name: must have 1 to 32 characters"}},
        {[](json& j) { j["courses"][0]["gates"][1]["width_m"] = 1; }, {"courses[0].gates[1].width_m: 1 is out of range [2, 40]"}},
        {[](json& j) { j["courses"][0]["gates"][0].erase("heading_deg"); }, {"courses[0].gates[0]: missing required key 'heading_deg'"}},
        {[](json& j) { j["courses"][0]["gates"][0]["posts"] = 2; }, {"courses[0].gates[0].posts: unknown key"}},
        {[](json& j) { j["courses"][0]["gates"][1]["centre_xz"] = {30, 20}; }, {"courses[0].gates[1]: a car's gate must stand on land"}},
        {[](json& j) { j["courses"][1]["gates"][1]["centre_xz"] = {30, -20}; }, {"courses[1].gates[1]: a boat's gate must stand on the sea"}},
        {[](json& j) { j["courses"][0]["gates"][0]["centre_xz"] = {-165, -10}; }, {"courses[0].gates[0]: a post lies outside the world"}},
        {[](json& j) { j["courses"] = json::array({j["courses"][0], j["courses"][0], j["courses"][0], j["courses"][0], j["courses"][0],
                                                    j["courses"][0], j["courses"][0], j["courses"][0], j["courses"][0]}); },
         {"courses: 9 entries, at most 8 allowed"}},
        {[](json& j) { j["targets"][0]["kind"] = "duck"; }, {"targets[0].kind: expected \"buoy\" or \"crate\", got \"duck\""}},
        {[](json& j) { j["targets"][0]["radius_m"] = 5; }, {"targets[0].radius_m: 5 is out of range [0.2, 3]"}},
        {[](json& j) { j["targets"][0] = {{"kind", "buoy"}, {"position", {10, 1, -20}}, {"radius_m", 1}}; },
         {"targets[0].position: a buoy must float on the sea"}},
        {[](json& j) { j["targets"][0] = {{"kind", "crate"}, {"position", {10, 1, 20}}, {"radius_m", 1}}; },
         {"targets[0].position: a crate must stand on land"}},
        {[](json& j) { j["targets"][0]["position"] = {500, 1, -20}; }, {"targets[0].position: lies outside the world"}},
    });
}
