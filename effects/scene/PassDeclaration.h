#pragma once
// What a pass reads and writes over the frame's named resources, and the check that a
// list of passes is in an order that works: every read after the resource's write,
// nothing written twice unless the later pass draws onto it and says why. No GL.
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

struct PassDeclaration {
    std::vector<FrameResource> reads;
    std::vector<FrameResource> writes;  // made anew: the first write of the frame
    std::vector<DrawOnto> onto;
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
