#include "effects/scene/PassDeclaration.h"

#include <map>

namespace effects {

namespace {

std::string quoted(std::string_view s) { return "\"" + std::string(s) + "\""; }

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
    for (const DeclaredPass& p : passes) {
        for (FrameResource r : p.declaration.reads) must_exist(p.name, r, "reads");
        for (const DrawOnto& o : p.declaration.onto) {
            no_frame_data(p.name, o.resource);
            must_exist(p.name, o.resource, "draws onto");
            if (o.why.empty())
                problems.push_back("pass " + quoted(p.name) + " draws onto " + quoted(name_of(o.resource)) +
                                   " without saying why");
        }
        for (FrameResource r : p.declaration.writes) {
            no_frame_data(p.name, r);
            if (auto it = written_by.find(r); it != written_by.end())
                problems.push_back("pass " + quoted(p.name) + " writes " + quoted(name_of(r)) + ", which pass " +
                                   quoted(it->second) + " already wrote; draw onto it and say why");
            else
                written_by.emplace(r, p.name);
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
    std::string out = "| # | pass | reads | writes | draws onto (why) |\n|---|---|---|---|---|\n";
    int n = 0;
    for (const DeclaredPass& p : passes) {
        std::string onto;
        for (const DrawOnto& o : p.declaration.onto)
            onto += (onto.empty() ? "" : "; ") + std::string(name_of(o.resource)) + " (" + std::string(o.why) + ")";
        out += "| " + std::to_string(++n) + " | `" + std::string(p.name) + "` | " + list(p.declaration.reads) + " | " +
               list(p.declaration.writes) + " | " + onto + " |\n";
    }
    return out;
}

}  // namespace effects
