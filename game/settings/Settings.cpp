#include "game/settings/Settings.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "game/settings/KeyNames.h"

namespace game {

using nlohmann::json;

namespace {

constexpr sim::ViewMode kViews[] = {sim::ViewMode::Chase, sim::ViewMode::Driver};
constexpr sim::WiperMode kWipers[] = {sim::WiperMode::Off, sim::WiperMode::Intermittent, sim::WiperMode::Low,
                                      sim::WiperMode::High};

// Reads the members of one JSON object, each into its field when it is valid, and
// notes a line naming the key (its path from the top) otherwise.
class Reader {
public:
    Reader(const json& object, std::string path, std::vector<std::string>& problems)
        : object_(object), path_(std::move(path)), problems_(problems) {}

    const json* member(const char* key) const {
        const auto it = object_.find(key);
        return it == object_.end() || it->is_null() ? nullptr : &*it;
    }
    std::string name(const char* key) const { return path_.empty() ? key : path_ + "." + key; }
    void problem(const char* key, const std::string& what) const {
        problems_.push_back(name(key) + ": " + what + "; using the default");
    }

    void boolean(const char* key, bool& out) const {
        const json* v = member(key);
        if (!v) return;
        if (v->is_boolean())
            out = v->get<bool>();
        else
            problem(key, "expected true or false, found " + v->dump());
    }
    void number(const char* key, float& out, float lo, float hi) const {
        const json* v = member(key);
        if (!v) return;
        if (!v->is_number()) return problem(key, "expected a number, found " + v->dump());
        const double d = v->get<double>();
        if (!std::isfinite(d) || d < lo || d > hi)
            return problem(key, v->dump() + " is outside " + fmt(lo) + ".." + fmt(hi));
        out = float(d);
    }
    void integer(const char* key, int& out, int lo, int hi) const {
        const json* v = member(key);
        if (!v) return;
        if (!v->is_number_integer()) return problem(key, "expected a whole number, found " + v->dump());
        const int64_t i = v->get<int64_t>();
        if (i < lo || i > hi)
            return problem(key, v->dump() + " is outside " + std::to_string(lo) + ".." + std::to_string(hi));
        out = int(i);
    }
    void optional_integer(const char* key, std::optional<int>& out, int lo, int hi) const {
        if (!member(key)) return;
        int value = 0;
        const size_t before = problems_.size();
        integer(key, value, lo, hi);
        if (problems_.size() == before) out = value;
    }
    template <typename T, size_t N>
    void choice(const char* key, T& out, const T (&options)[N], auto name_of) const {
        const json* v = member(key);
        if (!v) return;
        std::string known;
        for (T o : options) {
            if (v->is_string() && v->get<std::string>() == name_of(o)) {
                out = o;
                return;
            }
            known += std::string(known.empty() ? "" : ", ") + std::string(name_of(o));
        }
        problem(key, v->dump() + " is not one of " + known);
    }
    // A nested object, or none (a problem if it is something else).
    const json* object(const char* key) const {
        const json* v = member(key);
        if (v && !v->is_object()) {
            problem(key, "expected an object, found " + v->dump());
            return nullptr;
        }
        return v;
    }

private:
    static std::string fmt(float f) {
        std::string s = std::to_string(f);
        s.erase(s.find_last_not_of('0') + 1);
        if (s.back() == '.') s.pop_back();
        return s;
    }

    const json& object_;
    std::string path_;
    std::vector<std::string>& problems_;
};

void read_keys(const json& keys, KeyBindings& out, std::vector<std::string>& problems) {
    KeyBindings read;
    for (const auto& [id, value] : keys.items()) {
        const std::optional<Action> action = action_from_id(id);
        if (!action) {
            problems.push_back("keys." + id + ": no such action; ignored");
            continue;
        }
        KeyBindings::Keys slots{0, 0};
        bool ok = value.is_array() && value.size() <= size_t(KeyBindings::kSlots);
        for (size_t i = 0; ok && i < value.size(); ++i) {
            const std::optional<int> key = value[i].is_string() ? key_from_name(value[i].get<std::string>()) : std::nullopt;
            ok = key && *key != kMenuKey;
            if (ok) slots[i] = *key;
        }
        if (!ok) {
            problems.push_back("keys." + id + ": " + value.dump() +
                               " is not a list of up to two key names (Esc is the menu's); using the default");
            continue;
        }
        read.set_keys(*action, slots);
    }
    if (auto shared = read.first_shared_key()) {
        problems.push_back("keys." + std::string(action_info(shared->second).id) + ": shares a key with keys." +
                           std::string(action_info(shared->first).id) + "; using the default keys for every action");
        return;
    }
    out = read;
}

}  // namespace

const char* camera_setting_name(sim::ViewMode view) { return view == sim::ViewMode::Chase ? "chase" : "driver"; }

const char* wiper_setting_name(sim::WiperMode mode) {
    switch (mode) {
        case sim::WiperMode::Off: return "off";
        case sim::WiperMode::Intermittent: return "intermittent";
        case sim::WiperMode::Low: return "low";
        case sim::WiperMode::High: return "high";
    }
    return "off";
}

// Three decimals are plenty for a slider, and the file reads 0.35 rather than 0.3499999940395355.
static double tidy(float f) { return double(std::lround(double(f) * 1000.0)) / 1000.0; }

json settings_to_json(const Settings& s) {
    json keys = json::object();
    for (const ActionInfo& a : actions()) {
        json list = json::array();
        for (int k : s.keys.keys(a.action))
            if (k) list.push_back(key_name(k));
        keys[std::string(a.id)] = list;
    }
    json window = {{"width", s.window.width}, {"height", s.window.height}, {"fullscreen", s.window.fullscreen}};
    window["x"] = s.window.x ? json(*s.window.x) : json(nullptr);
    window["y"] = s.window.y ? json(*s.window.y) : json(nullptr);
    return {
        {"version", Settings::kVersion},
        {"quality", std::string(quality_choice_name(s.quality))},
        {"auto_render_scale", {{"min", tidy(s.auto_min_scale)}, {"max", tidy(s.auto_max_scale)}}},
        {"window", window},
        {"vsync", s.vsync},
        {"fxaa", s.fxaa},
        {"volume",
         {{"master", tidy(s.volume.master)}, {"engine", tidy(s.volume.engine)}, {"effects", tidy(s.volume.effects)},
          {"ambience", tidy(s.volume.ambience)}}},
        {"camera", camera_setting_name(s.camera)},
        {"wipers", wiper_setting_name(s.wipers)},
        {"keys", keys},
        {"menu_seen", s.menu_seen},
    };
}

Settings settings_from_json(const json& j, std::vector<std::string>& problems) {
    Settings s;
    if (!j.is_object()) {
        problems.push_back("the file is not a JSON object; using the defaults");
        return s;
    }
    const Reader top(j, "", problems);
    if (const json* v = top.member("version")) {
        if (!v->is_number_integer() || v->get<int64_t>() < 1) {
            top.problem("version", v->dump() + " is not a version number");
        } else if (v->get<int64_t>() > Settings::kVersion) {
            problems.push_back("version: " + v->dump() + " is from a newer Spindrift (this one reads " +
                               std::to_string(Settings::kVersion) + "); using the defaults");
            return s;
        }
    }
    static const std::vector<std::string> kKnown = {"version", "quality", "auto_render_scale", "window",
                                                    "vsync",   "fxaa",    "volume",            "camera",
                                                    "wipers",  "keys",    "menu_seen"};
    for (const auto& [key, value] : j.items())
        if (std::find(kKnown.begin(), kKnown.end(), key) == kKnown.end())
            problems.push_back(key + ": not a setting; ignored");

    top.choice("quality", s.quality, kQualityChoices, quality_choice_name);
    if (const json* scales = top.object("auto_render_scale")) {
        const Reader r(*scales, "auto_render_scale", problems);
        Settings read;
        r.number("min", read.auto_min_scale, kMinAutoScale, 1.0f);
        r.number("max", read.auto_max_scale, kMinAutoScale, 1.0f);
        if (read.auto_min_scale > read.auto_max_scale)
            problems.push_back("auto_render_scale: min is above max; using the default range");
        else
            s.auto_min_scale = read.auto_min_scale, s.auto_max_scale = read.auto_max_scale;
    }
    if (const json* window = top.object("window")) {
        const Reader r(*window, "window", problems);
        r.integer("width", s.window.width, kMinWindowSide, kMaxWindowSide);
        r.integer("height", s.window.height, kMinWindowSide / 2, kMaxWindowSide);
        r.optional_integer("x", s.window.x, -kMaxWindowSide, kMaxWindowSide);
        r.optional_integer("y", s.window.y, -kMaxWindowSide, kMaxWindowSide);
        r.boolean("fullscreen", s.window.fullscreen);
    }
    top.boolean("vsync", s.vsync);
    top.boolean("fxaa", s.fxaa);
    if (const json* volume = top.object("volume")) {
        const Reader r(*volume, "volume", problems);
        r.number("master", s.volume.master, 0.0f, 1.0f);
        r.number("engine", s.volume.engine, 0.0f, 1.0f);
        r.number("effects", s.volume.effects, 0.0f, 1.0f);
        r.number("ambience", s.volume.ambience, 0.0f, 1.0f);
    }
    top.choice("camera", s.camera, kViews, camera_setting_name);
    top.choice("wipers", s.wipers, kWipers, wiper_setting_name);
    if (const json* keys = top.object("keys")) read_keys(*keys, s.keys, problems);
    top.boolean("menu_seen", s.menu_seen);
    return s;
}

Settings with_changes(const Settings& stored, const Settings& before, const Settings& after) {
    // JSON Patch does the field-by-field work: what changed between before and after,
    // applied to what is stored.
    json merged = settings_to_json(stored);
    try {
        merged = merged.patch(json::diff(settings_to_json(before), settings_to_json(after)));
    } catch (const json::exception&) {
        return after;  // the shapes differ (not for settings this program wrote): take the whole
    }
    std::vector<std::string> ignored;
    return settings_from_json(merged, ignored);
}

}  // namespace game
