#include "game/DataPaths.h"

#include <cstdlib>
#include <system_error>

namespace game {

namespace fs = std::filesystem;

fs::path installed_data_dir(const fs::path& executable) {
    const fs::path dir = executable.parent_path().parent_path() / "share" / "spindrift";
    std::error_code ec;
    return fs::is_directory(dir / "levels", ec) ? dir : fs::path();
}

fs::path data_dir() {
    if (const char* env = std::getenv("SPINDRIFT_DATA"); env && *env) return env;
    // The running program's own file (Linux), wherever it was started from.
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        if (fs::path installed = installed_data_dir(self); !installed.empty()) return installed;
    }
    return SPINDRIFT_DATA_DIR;
}

}  // namespace game
