// The pass table's declarations (effects/PassList.cpp): the game's frame is in an order
// that works, the check finds each kind of mistake, and docs/ARCHITECTURE.md shows the
// declarations as they are. No GL.
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include <gtest/gtest.h>

#include "effects/PassList.h"

using namespace effects;
using enum FrameResource;

TEST(PassDeclaration, TheGameFrameReadsEverythingAfterItIsWritten) {
    EXPECT_EQ(check_pass_order(declared_passes()), std::vector<std::string>{});
}

TEST(PassDeclaration, PassNamesAreUniqueAndFoundByName) {
    std::set<std::string_view> names;
    for (const PassEntry& e : pass_table()) EXPECT_TRUE(names.insert(e.name).second) << e.name;
    EXPECT_EQ(pass_index("environment"), 0u);
    EXPECT_EQ(pass_index("upscale"), pass_table().size() - 1);
    EXPECT_THROW(pass_index("mirror of nothing"), std::invalid_argument);
}

TEST(PassDeclaration, AReadBeforeItsWriteIsFound) {
    const std::vector<DeclaredPass> passes{{"water", {.reads = {SceneCopy}}}, {"scene_copy", {.writes = {SceneCopy}}}};
    const auto problems = check_pass_order(passes);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0], "pass \"water\" reads \"scene copy\" before any pass writes it");
}

TEST(PassDeclaration, ASecondWriteMustDrawOntoAndSayWhy) {
    const std::vector<DeclaredPass> twice{{"opaque", {.writes = {SceneColour}}},
                                          {"glow", {.writes = {SceneColour}}},
                                          {"tonemap", {.reads = {SceneColour}, .writes = {Output}}}};
    const auto problems = check_pass_order(twice);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0], "pass \"glow\" writes \"scene colour\", which pass \"opaque\" already wrote; draw onto it "
                           "and say why");

    const std::vector<DeclaredPass> onto{{"opaque", {.writes = {SceneColour}}},
                                         {"glow", {.onto = {{SceneColour, "added"}}}},
                                         {"tonemap", {.reads = {SceneColour}, .writes = {Output}}}};
    EXPECT_EQ(check_pass_order(onto), std::vector<std::string>{});

    const std::vector<DeclaredPass> silent{{"opaque", {.writes = {SceneColour}}},
                                           {"glow", {.onto = {{SceneColour, ""}}}},
                                           {"tonemap", {.reads = {SceneColour}, .writes = {Output}}}};
    EXPECT_EQ(check_pass_order(silent),
              std::vector<std::string>{"pass \"glow\" draws onto \"scene colour\" without saying why"});
}

TEST(PassDeclaration, ACopyIsRefreshedOnlyAfterADrawOntoWhatItCopies) {
    const DeclaredPass opaque{"opaque", {.writes = {SceneColour, Depth}}};
    const DeclaredPass copy{"scene_copy", {.reads = {SceneColour, Depth}, .writes = {SceneCopy}}};
    const DeclaredPass water{"water", {.reads = {SceneCopy}, .onto = {{SceneColour, "the sea"}}}};
    const DeclaredPass fluid{"fluid",
                             {.reads = {SceneCopy}, .onto = {{SceneColour, "the tank"}}, .refreshes = {{SceneCopy, "the sea"}}}};
    const DeclaredPass rain{"rain", {.reads = {SceneCopy}, .refreshes = {{SceneCopy, "with mips"}}}};
    const DeclaredPass tonemap{"tonemap", {.reads = {SceneColour}, .writes = {Output}}};
    // The fluid's own draw counts for the rain after it.
    EXPECT_EQ(check_pass_order({opaque, copy, water, fluid, rain, tonemap}), std::vector<std::string>{});

    EXPECT_EQ(check_pass_order({opaque, copy, rain, tonemap}),
              std::vector<std::string>{
                  "pass \"rain\" refreshes \"scene copy\", but no pass drew onto \"scene colour\" since it was copied"});
    // A second refresh with nothing drawn between.
    EXPECT_EQ(check_pass_order({opaque, copy, water, rain, rain, tonemap}),
              std::vector<std::string>{
                  "pass \"rain\" refreshes \"scene copy\", but no pass drew onto \"scene colour\" since it was copied"});

    const DeclaredPass early{"fluid", {.onto = {{SceneColour, "the tank"}}, .refreshes = {{SceneCopy, "the sea"}}}};
    EXPECT_EQ(check_pass_order({opaque, early, copy, water, tonemap}),
              std::vector<std::string>{"pass \"fluid\" refreshes \"scene copy\" before any pass writes it"});

    const DeclaredPass silent{"fluid", {.reads = {SceneCopy}, .onto = {{SceneColour, "the tank"}}, .refreshes = {{SceneCopy, ""}}}};
    EXPECT_EQ(check_pass_order({opaque, copy, water, silent, tonemap}),
              std::vector<std::string>{"pass \"fluid\" refreshes \"scene copy\" without saying why"});

    const DeclaredPass not_a_copy{"fluid", {.onto = {{SceneColour, "the tank"}}, .refreshes = {{Depth, "the sea"}}}};
    EXPECT_EQ(check_pass_order({opaque, copy, water, not_a_copy, tonemap}),
              std::vector<std::string>{"pass \"fluid\" refreshes \"depth\", which is no copy"});
}

TEST(PassDeclaration, FrameDataIsReadOnlyToPasses) {
    const std::vector<DeclaredPass> passes{{"shadow", {.reads = {Sky}, .writes = {Sky, Output}}}};
    EXPECT_EQ(check_pass_order(passes),
              std::vector<std::string>{
                  "pass \"shadow\" writes \"sky\", frame data made before the passes and read-only to them"});
}

TEST(PassDeclaration, WhatNoPassUsesIsFound) {
    const std::vector<DeclaredPass> passes{{"scene_copy", {.writes = {SceneCopy}}}};
    EXPECT_EQ(check_pass_order(passes),
              std::vector<std::string>{"pass \"scene_copy\" writes \"scene copy\", which no pass uses"});
}

// The table in docs/ARCHITECTURE.md is made by declaration_table(); if this fails, paste
// the expected table printed below over the one in the page.
TEST(PassDeclaration, TheArchitecturePageShowsTheDeclarations) {
    std::ifstream in(std::string(SPINDRIFT_DOCS_DIR) + "/ARCHITECTURE.md");
    ASSERT_TRUE(in) << "cannot read docs/ARCHITECTURE.md";
    std::stringstream page;
    page << in.rdbuf();
    const std::string table = declaration_table(declared_passes());
    EXPECT_NE(page.str().find(table), std::string::npos) << "docs/ARCHITECTURE.md should hold:\n" << table;
}
