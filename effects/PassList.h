#pragma once
// The frame's passes, in order: each one's name, what it reads and writes, and how it
// is made. An effect adds its row to the table in PassList.cpp, after what it reads.
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "effects/scene/Pass.h"
#include "effects/scene/PassDeclaration.h"

namespace effects {

struct PassEntry {
    std::string_view name;  // the pass's name(): timers, debug groups, stages pick by it
    PassDeclaration declaration;
    std::unique_ptr<Pass> (*make)();
};

// In frame order.
const std::vector<PassEntry>& pass_table();
// The table's names and declarations (for check_pass_order and declaration_table).
std::vector<DeclaredPass> declared_passes();
// Where `name` is in the table; throws std::invalid_argument for a name it lacks.
size_t pass_index(std::string_view name);
// Some of the table's passes, picked by name; made, they run in the table's order.
class PassSet {
public:
    PassSet() = default;
    // Throws std::invalid_argument for a name the table lacks.
    static PassSet of(std::initializer_list<std::string_view> names);
    static PassSet all();
    bool contains(size_t index) const { return (bits_ >> index) & 1u; }
    bool empty() const { return bits_ == 0; }
    PassSet operator|(PassSet o) const { return PassSet(bits_ | o.bits_); }
    PassSet operator&(PassSet o) const { return PassSet(bits_ & o.bits_); }
    PassSet operator~() const { return PassSet(~bits_ & all().bits_); }
    explicit operator bool() const { return !empty(); }
    bool operator==(const PassSet&) const = default;

private:
    explicit PassSet(uint64_t bits) : bits_(bits) {}
    uint64_t bits_ = 0;
};

// The passes of `set`, made, in the table's order.
std::vector<std::unique_ptr<Pass>> make_passes(PassSet set);
// Every pass of the table, made, in order.
std::vector<std::unique_ptr<Pass>> make_pass_list();

}  // namespace effects
