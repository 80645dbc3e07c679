// Resource limits: a level's memory budget (budget_mib) and its estimated terms, absurd
// sizes refused with a message naming them before anything that size is allocated (shown
// under a tight address-space limit), and the program's real peak memory within the
// budget of the level it runs.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include "game/DataPaths.h"
#include "game/level/GltfModel.h"
#include "game/level/LevelLoader.h"
#include "game/level/LevelMemory.h"
#include "game/replay/Crc32.h"
#include "game/replay/InputScript.h"
#include "game/replay/ReplayReader.h"
#include "game/replay/ReplayWriter.h"

namespace fs = std::filesystem;

namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

std::string read_file(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

const fs::path& harbour_json() {
    static const fs::path path = fs::path(SPINDRIFT_TEST_DATA).parent_path().parent_path() / "levels" / "harbour.json";
    return path;
}

// The harbour's JSON with `from` replaced by `to`.
std::string harbour_with(const std::string& from, const std::string& to) {
    std::string json = read_file(harbour_json());
    const size_t at = json.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) json.replace(at, from.size(), to);
    return json;
}

// The LevelError message of loading `json` as the harbour, or "" if it loads.
std::string level_error(const std::string& json) {
    try {
        game::load_level_text(harbour_json(), json);
        return "";
    } catch (const game::LevelError& e) {
        return e.what();
    }
}

void expect_words(const std::string& message, std::initializer_list<const char*> words) {
    EXPECT_FALSE(message.empty()) << "no error; expected one mentioning " << *words.begin();
    for (const char* w : words) EXPECT_NE(message.find(w), std::string::npos) << message << "\nlacks: " << w;
}

// Runs `body` in a child limited to its current address space plus `headroom_bytes`:
// an allocation the size of an absurd request would fail there (std::bad_alloc, exit 5).
// Returns the child's exit code.
int exit_code_with_little_memory(uint64_t headroom_bytes, const std::function<int()>& body) {
    const pid_t child = ::fork();
    if (child == 0) {
        long pages = 0;
        if (FILE* f = std::fopen("/proc/self/statm", "r")) {
            if (std::fscanf(f, "%ld", &pages) != 1) pages = 0;
            std::fclose(f);
        }
        const rlim_t limit = rlim_t(pages) * rlim_t(::sysconf(_SC_PAGESIZE)) + headroom_bytes;
        const rlimit as{limit, limit};
        if (pages == 0 || ::setrlimit(RLIMIT_AS, &as) != 0) ::_exit(6);
        try {
            ::_exit(body());
        } catch (const std::bad_alloc&) {
            ::_exit(5);
        } catch (...) {
            ::_exit(7);
        }
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

struct RunResult {
    int code = -1;
    std::string output;
    long peak_rss_kib = 0;
};

// Runs the program with `args` (output to a file), with its peak resident memory.
RunResult run_measured(const std::vector<std::string>& args, const fs::path& log) {
    const pid_t child = ::fork();
    if (child == 0) {
        if (!std::freopen(log.c_str(), "w", stdout) || !::dup2(::fileno(stdout), 2)) ::_exit(126);
        std::vector<char*> argv{const_cast<char*>(SPINDRIFT_BIN)};
        for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        ::execv(SPINDRIFT_BIN, argv.data());
        ::_exit(127);
    }
    int status = 0;
    rusage usage{};
    ::wait4(child, &status, 0, &usage);
    RunResult r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.output = read_file(log);
    r.peak_rss_kib = usage.ru_maxrss;
    return r;
}

class Limits : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("spindrift_limits_" + std::to_string(::getpid()) + "_" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

}  // namespace

TEST(LevelBudget, TheHarbourFitsItsBudgetWithEveryTermNamed) {
    const game::LoadedLevel level = game::load_level_text(harbour_json(), read_file(harbour_json()));
    const game::MemoryBudget& m = level.memory;
    EXPECT_LE(m.used_bytes(), m.budget_bytes());
    std::string names;
    uint64_t sum = 0;
    for (const game::MemoryTerm& t : m.terms()) {
        names += t.name + "; ";
        sum += t.bytes;
    }
    EXPECT_EQ(sum, m.used_bytes());
    for (const char* term : {"program base", "water: wave grid 256x256", "model warehouse.gltf", "model car.gltf"})
        EXPECT_NE(names.find(term), std::string::npos) << names << "\nlacks: " << term;
}

TEST(LevelBudget, BadBudgetsAreRefusedNamingTheField) {
    for (const char* bad : {"-1", "12.5", "\"512\"", "true", "10", "1000000", "18446744073709551616"}) {
        SCOPED_TRACE(bad);
        expect_words(level_error(harbour_with("\"budget_mib\": 512", std::string("\"budget_mib\": ") + bad)),
                     {"harbour.json", "budget_mib", "64 to 65536"});
    }
}

TEST(LevelBudget, ALevelThatNeedsMoreThanItsBudgetIsRefusedBeforeItsWorldExists) {
    // Even the program's base does not fit 64 MiB.
    expect_words(level_error(harbour_with("\"budget_mib\": 512", "\"budget_mib\": 64")),
                 {"harbour.json: budget_mib", "program base", "more than its budget of 64.0 MiB"});
    // The largest wave grid the sim allows, in a budget too small for it: refused with the
    // grid named as the largest term, before any of it (or any asset) is allocated.
    const std::string big_grid = harbour_with("\"grid_size\": 256", "\"grid_size\": 2048");
    EXPECT_EQ(level_error(harbour_with("\"budget_mib\": 512", "\"budget_mib\": 300")), "");
    std::string tight = big_grid;
    tight.replace(tight.find("\"budget_mib\": 512"), 17, "\"budget_mib\": 300");
    expect_words(level_error(tight), {"budget_mib", "water: wave grid 2048x2048 192.0 MiB", "300.0 MiB"});
    // The same grid with room for it loads.
    tight.replace(tight.find("\"budget_mib\": 300"), 17, "\"budget_mib\": 600");
    EXPECT_EQ(level_error(tight), "");
}

TEST(LevelBudget, FramesAreChargedPerPixel) {
    game::MemoryBudget budget("level.json", 512 * game::kMiB);
    game::charge_frame_memory(1920, 1080, budget);
    EXPECT_EQ(budget.terms().back().name, "frames 1920x1080");
    EXPECT_EQ(budget.used_bytes(), game::kRendererBaseBytes + 1920u * 1080u * 128u);
    try {
        game::charge_frame_memory(4096, 4096, budget);
        ADD_FAILURE() << "4096x4096 frames fit 512 MiB";
    } catch (const game::LevelError& e) {
        expect_words(e.what(), {"level.json: budget_mib", "frames 4096x4096 2048.0 MiB", "512.0 MiB"});
    }
}

// Absurd sizes in each kind of input are refused by their check, not by running out of
// memory: with only 64 MiB of address space to spare, each still gets its message.
TEST_F(Limits, AbsurdSizesAreRefusedBeforeAnyLargeAllocation) {
    if (kAddressSanitizer) GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space";
    constexpr uint64_t kHeadroom = 64 * game::kMiB;

    // A replay chunk that claims 4 billion ticks (its header CRC fixed, as a forger would).
    const fs::path replay = dir_ / "r.replay";
    {
        game::ReplayHeader h;
        h.level_id = "harbour";
        h.subsystem_names = {"car"};
        game::ReplayWriter w = game::ReplayWriter::create(replay, h);
        for (uint32_t t = 0; t < 60; ++t) w.append(sim::TickInput{}, sim::WorldHash{t, {t}});
        w.finish();
    }
    std::string bytes = read_file(replay);
    const size_t chunk = game::replay_bytes::get_u32(reinterpret_cast<const uint8_t*>(bytes.data()) + 12);
    auto set_u32 = [&](size_t at, uint32_t v) {
        for (int i = 0; i < 4; ++i) bytes[at + size_t(i)] = char(uint8_t(v >> (8 * i)));
    };
    set_u32(chunk + 8, 0xFFFFFFFFu);
    set_u32(chunk + 16, game::crc32(std::span<const uint8_t>(reinterpret_cast<const uint8_t*>(bytes.data()) + chunk, 16)));
    EXPECT_EQ(exit_code_with_little_memory(kHeadroom, [&] {
                  try {
                      game::parse_replay(std::span<const uint8_t>(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()), "r");
                  } catch (const game::ReplayError& e) {
                      return std::string(e.what()).find("4294967295 ticks") != std::string::npos ? 0 : 1;
                  }
                  return 2;
              }),
              0);

    // A script asking for more ticks than a replay holds.
    EXPECT_EQ(exit_code_with_little_memory(kHeadroom, [] {
                  try {
                      game::parse_script("0 hold throttle\n4000000000 end\n", "s");
                  } catch (const game::ScriptError& e) {
                      return std::string(e.what()).find("above the limit") != std::string::npos ? 0 : 1;
                  }
                  return 2;
              }),
              0);

    // Level sizes: a huge wave grid, tens of thousands of props.
    std::string props = "\"props\": [";
    for (int i = 0; i < 5000; ++i) props += "{\"asset\": \"pine.gltf\", \"position\": [0, 0, 0]},";
    const struct {
        std::string json;
        const char* says;
    } levels[] = {
        {harbour_with("\"grid_size\": 256", "\"grid_size\": 1000000"), "water.grid_size"},
        {harbour_with("\"props\": [", props), "props: 5"},
    };
    for (const auto& level : levels)
        EXPECT_EQ(exit_code_with_little_memory(kHeadroom,
                                               [&] {
                                                   const std::string message = level_error(level.json);
                                                   return message.find(level.says) != std::string::npos ? 0 : 1;
                                               }),
                  0)
            << level.says;

    // glTF counts and lengths far beyond the file: an accessor of 2^31 elements, a buffer
    // claiming a terabyte.
    const std::string triangle = read_file(fs::path(SPINDRIFT_TEST_DATA).parent_path() / "fuzz" / "corpus" / "gltf_model" / "triangle.gltf");
    const struct {
        std::string from, to;
    } gltfs[] = {{"\"count\": 3, \"type\": \"VEC3\"", "\"count\": 2147483648, \"type\": \"VEC3\""},
                 {"\"byteLength\": 56", "\"byteLength\": 1099511627776"}};
    for (const auto& g : gltfs) {
        std::string gltf = triangle;
        const size_t at = gltf.find(g.from);
        ASSERT_NE(at, std::string::npos) << g.from;
        gltf.replace(at, g.from.size(), g.to);
        EXPECT_EQ(exit_code_with_little_memory(kHeadroom,
                                               [&] {
                                                   try {
                                                       game::parse_gltf_model(gltf, dir_ / "t.gltf");
                                                   } catch (const game::LevelError&) {
                                                       return 0;
                                                   }
                                                   return 2;
                                               }),
                  0)
            << g.to;
    }
}

// A replay whose frames would not fit the level's budget is refused before any GL
// context or render target exists.
TEST_F(Limits, AReplayWithFramesTooLargeForTheLevelIsRefused) {
    const fs::path script = dir_ / "big.script", out = dir_ / "big.replay";
    std::ofstream(script) << "level harbour\nframes 4096x4096\ncheckpoints 10\n0 hold throttle\n20 end\n";
    RunResult rec = run_measured({"record", "--script", script.string(), "--out", out.string()}, dir_ / "rec.log");
    ASSERT_EQ(rec.code, 0) << rec.output;
    RunResult r = run_measured({"replay", out.string(), "--headless", "--check"}, dir_ / "replay.log");
    EXPECT_EQ(r.code, 3) << r.output;
    expect_words(r.output, {"harbour.json: budget_mib", "frames 4096x4096"});
    // Hashes only: no frames, nothing to charge.
    EXPECT_EQ(run_measured({"replay", out.string(), "--headless", "--check", "--frames", "none"}, dir_ / "n.log").code, 0);
}

// The budget is a real bound: recording and checking the bundled replays, frames
// included, stays within what the harbour states (and within what was charged for it).
TEST_F(Limits, PeakMemoryStaysWithinTheLevelBudget) {
    if (kAddressSanitizer) GTEST_SKIP() << "AddressSanitizer's shadow memory and quarantine inflate the resident size";
    const game::LoadedLevel level = game::load_level("harbour");
    game::MemoryBudget charged = level.memory;
    const fs::path drive = fs::path(SPINDRIFT_TEST_DATA).parent_path().parent_path() / "replays" / "harbour_drive.replay";
    const game::Replay replay = game::read_replay(drive);
    game::charge_frame_memory(replay.header.frame_width, replay.header.frame_height, charged);

    const RunResult check = run_measured(
        {"replay", drive.string(), "--headless", "--check", "--frames", "90", "--out", (dir_ / "frames").string()},
        dir_ / "check.log");
    ASSERT_EQ(check.code, 0) << check.output;
    const uint64_t peak = uint64_t(check.peak_rss_kib) * 1024;
    std::printf("replay check: peak %s, charged %s, budget %s\n", game::show_mib(peak).c_str(),
                game::show_mib(charged.used_bytes()).c_str(), game::show_mib(charged.budget_bytes()).c_str());
    EXPECT_LE(peak, charged.used_bytes());
    EXPECT_LE(charged.used_bytes(), charged.budget_bytes());
}
