// The sim refuses to step in a floating-point environment other than the one its results
// are defined in (sim/core/FloatEnvironment.h), with a message that names what differs.
#include <gtest/gtest.h>

#include <cfenv>
#include <cstdint>
#include <string>

#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#endif

#include "SimTestLevel.h"
#include "sim/core/FloatEnvironment.h"
#include "sim/world/World.h"

namespace {

// The message of the FloatEnvironmentError that fn throws, or "" if it throws none.
template <class Fn>
std::string refusal(Fn fn) {
    try {
        fn();
    } catch (const sim::FloatEnvironmentError& e) {
        return e.what();
    }
    return "";
}

// Sets the flush-to-zero control of this thread for its lifetime.
class FlushToZero {
public:
    FlushToZero() {
#if defined(__SSE__) || defined(__x86_64__)
        saved_ = _mm_getcsr();
        _mm_setcsr(unsigned(saved_) | 0x8000u);
#elif defined(__aarch64__)
        asm volatile("mrs %0, fpcr" : "=r"(saved_));
        asm volatile("msr fpcr, %0" : : "r"(saved_ | (uint64_t(1) << 24)));
#endif
    }
    ~FlushToZero() {
#if defined(__SSE__) || defined(__x86_64__)
        _mm_setcsr(unsigned(saved_));
#elif defined(__aarch64__)
        asm volatile("msr fpcr, %0" : : "r"(saved_));
#endif
    }
    FlushToZero(const FlushToZero&) = delete;
    FlushToZero& operator=(const FlushToZero&) = delete;

private:
    uint64_t saved_ = 0;
};

TEST(FloatEnvironment, TheDefaultOneIsWhatTheSimNeeds) {
    EXPECT_EQ(sim::float_environment_problem(), "");
    sim::World world(make_test_level(), sim::WorldOptions{2});
    EXPECT_NO_THROW(world.step(sim::TickInput{}));
}

TEST(FloatEnvironment, FlushingSubnormalsIsRefusedAtTheNextStep) {
    sim::World world(make_test_level());
    world.step(sim::TickInput{});
    std::string message;
    {
        FlushToZero ftz;
        volatile float tiny = 1e-40f;  // subnormal: proves the flag took effect
        volatile float half = tiny * 0.5f;
        EXPECT_EQ(half, 0.0f);
        message = refusal([&] { world.step(sim::TickInput{}); });
    }
    EXPECT_NE(message.find("flushed to zero"), std::string::npos) << message;
    EXPECT_NE(message.find("-ffast-math"), std::string::npos) << message;
    EXPECT_EQ(world.tick(), 1u) << "the refused step must not have run";
    world.step(sim::TickInput{});  // restored: runs again
    EXPECT_EQ(world.tick(), 2u);
}

TEST(FloatEnvironment, AnotherRoundingModeIsRefused) {
    sim::World world(make_test_level());
    ASSERT_EQ(std::fesetround(FE_UPWARD), 0);
    const std::string message = refusal([&] { world.step(sim::TickInput{}); });
    std::fesetround(FE_TONEAREST);
    EXPECT_NE(message.find("round-to-nearest"), std::string::npos) << message;
}

TEST(FloatEnvironment, WorkerThreadsAreNotStartedInAWrongOne) {
    FlushToZero ftz;
    const std::string message = refusal([] { sim::World world(make_test_level(), sim::WorldOptions{2}); });
    EXPECT_NE(message.find("flushed to zero"), std::string::npos) << message;
}

}  // namespace
