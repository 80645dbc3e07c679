#include "effects/scene/PassDeclaration.h"

#include <map>

namespace effects {

namespace {

// Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on "\"" + string.
std::string quoted(std::string_view s) {
    std::string q;
    q.reserve(s.size() + 2);
    q.append(1, '"').append(s).append(1, '"');
    return q;
}

}  // namespace

std::vector<std::string> check_pass_order(const std::vector<DeclaredPass>& passes) {
    std::vector<std::string> problems;
    std::map<FrameResource, std::string_view> written_by;  // the pass that made it
    auto must_exist = [&](std::string_view pass, FrameResource r, std::string_view how) {
        if (!is_frame_data(r) && !written_by.contains(r))
            problems.push_back("pass " + quoted(pass) + " " + std::string(how) + " " + quoted(name_of(r)) +
                               " before any pass writes it");
    };
    auto no_frame_data = [&](std::string_view pass, FrameResource r) {
        if (is_frame_data(r))
            problems.push_back("pass " + quoted(pass) + " writes " + quoted(name_of(r)) +
                               ", frame data made before the passes and read-only to them");
    };
    // Per copy: whether a pass drew onto or wrote what it copies since it was last copied.
    std::map<FrameResource, bool> behind;
    auto changed = [&](FrameResource source) {
        for (auto& [copy, stale] : behind) stale |= copied_from(copy) == source;
    };
    for (const DeclaredPass& p : passes) {
        for (FrameResource r : p.declaration.reads) must_exist(p.name, r, "reads");
        // Before the pass's own draws.
        for (const Refresh& f : p.declaration.refreshes) {
            if (!is_copy(f.copy)) {
                problems.push_back("pass " + quoted(p.name) + " refreshes " + quoted(name_of(f.copy)) +
                                   ", which is no copy");
                continue;
            }
            must_exist(p.name, f.copy, "refreshes");
            if (f.why.empty())
                problems.push_back("pass " + quoted(p.name) + " refreshes " + quoted(name_of(f.copy)) +
                                   " without saying why");
            if (auto it = behind.find(f.copy); it != behind.end() && !it->second)
                problems.push_back("pass " + quoted(p.name) + " refreshes " + quoted(name_of(f.copy)) +
                                   ", but no pass drew onto " + quoted(name_of(copied_from(f.copy))) +
                                   " since it was copied");
            behind[f.copy] = false;
        }
        for (const DrawOnto& o : p.declaration.onto) {
            no_frame_data(p.name, o.resource);
            must_exist(p.name, o.resource, "draws onto");
            if (o.why.empty())
                problems.push_back("pass " + quoted(p.name) + " draws onto " + quoted(name_of(o.resource)) +
                                   " without saying why");
            changed(o.resource);
        }
        for (FrameResource r : p.declaration.writes) {
            no_frame_data(p.name, r);
            if (auto it = written_by.find(r); it != written_by.end())
                problems.push_back("pass " + quoted(p.name) + " writes " + quoted(name_of(r)) + ", which pass " +
                                   quoted(it->second) + " already wrote; draw onto it and say why");
            else
                written_by.emplace(r, p.name);
            changed(r);
            if (is_copy(r)) behind[r] = false;
        }
    }
    // What is made and never used is wasted work (the output is the frame's result).
    for (const auto& [r, writer] : written_by) {
        if (r == FrameResource::Output) continue;
        bool used = false;
        for (const DeclaredPass& p : passes) {
            for (FrameResource read : p.declaration.reads) used |= read == r;
            for (const DrawOnto& o : p.declaration.onto) used |= o.resource == r;
        }
        if (!used) problems.push_back("pass " + quoted(writer) + " writes " + quoted(name_of(r)) + ", which no pass uses");
    }
    return problems;
}

std::string declaration_table(const std::vector<DeclaredPass>& passes) {
    auto list = [](const std::vector<FrameResource>& rs) {
        std::string s;
        for (FrameResource r : rs) s += (s.empty() ? "" : ", ") + std::string(name_of(r));
        return s;
    };
    std::string out =
        "| # | pass | reads | writes | draws onto (why) | refreshes (why) |\n|---|---|---|---|---|---|\n";
    int n = 0;
    for (const DeclaredPass& p : passes) {
        std::string onto, refreshes;
        for (const DrawOnto& o : p.declaration.onto)
            onto += (onto.empty() ? "" : "; ") + std::string(name_of(o.resource)) + " (" + std::string(o.why) + ")";
        for (const Refresh& f : p.declaration.refreshes)
            refreshes += (refreshes.empty() ? "" : "; ") + std::string(name_of(f.copy)) + " (" + std::string(f.why) + ")";
        out += "| " + std::to_string(++n) + " | `" + std::string(p.name) + "` | " + list(p.declaration.reads) + " | " +
               list(p.declaration.writes) + " | " + onto + " | " + refreshes + " |\n";
    }
    return out;
}

}  // namespace effects
