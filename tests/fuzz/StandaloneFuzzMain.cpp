// Runs a fuzz target's LLVMFuzzerTestOneInput once on every file named on the command
// line or found under a named folder, in name order, without libFuzzer: builds that are
// not fuzzing still replay the seeds and the kept crash inputs. A crash or sanitizer
// report fails the run like under libFuzzer; the file being run is printed first.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace fs = std::filesystem;

int main(int argc, char** argv) {
    std::vector<fs::path> inputs;
    for (int i = 1; i < argc; ++i) {
        const fs::path arg = argv[i];
        std::error_code ec;
        if (fs::is_directory(arg, ec)) {
            for (const fs::directory_entry& e : fs::recursive_directory_iterator(arg, ec))
                if (e.is_regular_file()) inputs.push_back(e.path());
        } else if (fs::is_regular_file(arg, ec)) {
            inputs.push_back(arg);
        } else {
            std::fprintf(stderr, "fuzz driver: %s is neither a file nor a folder\n", argv[i]);
            return 2;
        }
    }
    std::sort(inputs.begin(), inputs.end());
    for (const fs::path& path : inputs) {
        std::fprintf(stderr, "running %s\n", path.c_str());
        std::ifstream in(path, std::ios::binary);
        if (!in) {
            std::fprintf(stderr, "fuzz driver: cannot read %s\n", path.c_str());
            return 2;
        }
        const std::vector<uint8_t> read{std::istreambuf_iterator<char>(in), {}};
        // A copy holds exactly the input's bytes, as libFuzzer passes them, so ASan sees overreads.
        const std::vector<uint8_t> bytes(read);
        LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
    }
    std::fprintf(stderr, "fuzz driver: %zu inputs ran\n", inputs.size());
    return 0;
}
