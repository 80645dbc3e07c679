#pragma once
// The GL tests' fixture: one headless GL context (game::HeadlessContext) for each test
// suite, made before its first test and destroyed after its last, current in every
// test. A suite derives from it and adds what its tests share; a SetUp of its own
// calls HeadlessTest::SetUp() first.
#include <memory>

#include <gtest/gtest.h>

#include "game/platform/HeadlessContext.h"

class HeadlessTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() { context_ = std::make_unique<game::HeadlessContext>(); }
    static void TearDownTestSuite() { context_.reset(); }
    void SetUp() override { context_->make_current(); }

private:
    static inline std::unique_ptr<game::HeadlessContext> context_;
};
