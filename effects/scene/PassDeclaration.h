#pragma once
// What a pass reads and writes over the frame's named resources, and the check that a
// list of passes is in an order that works: every read after the resource's write,
// nothing written twice unless the later pass draws onto it and says why, a copy
// refreshed only when something was drawn onto what it copies since. No GL.
#include <string>
#include <string_view>
#include <vector>

#include "effects/scene/FrameResource.h"

namespace effects {

// A later pass drawing over what an earlier one wrote (it reads what is there, too).
struct DrawOnto {
    FrameResource resource;
    std::string_view why;
};

// A pass copying into a copy an earlier pass made (is_copy()) again, all of it or a part,
// before its draws: what passes drew onto the copied resource since is in the copy then.
struct Refresh {
    FrameResource copy;
    std::string_view why;
};

struct PassDeclaration {
    std::vector<FrameResource> reads;
    std::vector<FrameResource> writes;  // made anew: the first write of the frame
    std::vector<DrawOnto> onto;
    std::vector<Refresh> refreshes;
};

struct DeclaredPass {
    std::string_view name;
    PassDeclaration declaration;
};

// The problems with running `passes` in this order, one sentence each; empty if none.
std::vector<std::string> check_pass_order(const std::vector<DeclaredPass>& passes);

// The declarations as a Markdown table (docs/ARCHITECTURE.md holds a copy, checked by a test).
std::string declaration_table(const std::vector<DeclaredPass>& passes);

}  // namespace effects
