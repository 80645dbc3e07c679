#include "game/settings/SettingsFile.h"


#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace game {

namespace fs = std::filesystem;

fs::path default_settings_path() {
    fs::path base;
    if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && fs::path(xdg).is_absolute())
        base = xdg;
    else if (const char* home = std::getenv("HOME"); home && *home)
        base = fs::path(home) / ".config";
    else
        return {};
    return base / "spindrift" / "settings.json";
}

SettingsFile::SettingsFile(fs::path path) : path_(std::move(path)) {
    std::error_code ec;
    if (path_.empty() || !fs::exists(path_, ec)) return;
    std::ifstream in(path_, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    if (!in) {
        problems_.push_back("cannot be read (" + std::string(std::strerror(errno)) + "); using the defaults");
        return;
    }
    nlohmann::json json;
    try {
        json = nlohmann::json::parse(text.str());
    } catch (const nlohmann::json::parse_error& e) {
        // e.what() reads "[json.exception.parse_error.101] parse error at line 3, column 5: ...".
        std::string why = e.what();
        if (const size_t at = why.find("] "); at != std::string::npos) why = why.substr(at + 2);
        problems_.push_back("is not valid JSON (" + why + "); using the defaults");
        return;
    }
    settings_ = settings_from_json(json, problems_);
}

bool SettingsFile::save(const Settings& settings, std::string& error) {
    if (settings == settings_ && fs::exists(path_)) return true;
    settings_ = settings;
    if (path_.empty()) {
        error = "no place for the settings file (neither XDG_CONFIG_HOME nor HOME is set)";
        return false;
    }
    const fs::path temporary = path_.string() + ".tmp";
    try {
        fs::create_directories(path_.parent_path());
        {
            std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
            out << settings_to_json(settings).dump(2) << "\n";
            out.flush();
            if (!out) throw fs::filesystem_error("cannot write", temporary, std::make_error_code(std::errc::io_error));
        }
        fs::rename(temporary, path_);
    } catch (const fs::filesystem_error& e) {
        std::error_code ignored;
        fs::remove(temporary, ignored);
        error = "cannot write " + path_.string() + ": " + e.code().message();
        return false;
    }
    return true;
}

}  // namespace game
