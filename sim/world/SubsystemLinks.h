#pragma once
// What a subsystem may read of the others, handed to it once when the world is
// assembled (Subsystem::connect): it keeps the references and looks nothing up per tick.
// It answers only for the subsystems the asker's entry in the list declares.
#include <memory>
#include <string_view>
#include <vector>

namespace sim {

class Subsystem;
struct SubsystemEntry;

class SubsystemLinks {
public:
    SubsystemLinks(const SubsystemEntry& asker, const std::vector<std::unique_ptr<Subsystem>>& subsystems)
        : asker_(asker), subsystems_(subsystems) {}

    // One the entry declares in `reads`: the world has it (assembly checked).
    template <class T> const T& need() const { return static_cast<const T&>(*find(T::kName, true)); }
    // One the entry declares in `may_read`: nullptr when this world has none.
    template <class T> const T* may() const { return static_cast<const T*>(find(T::kName, false)); }

private:
    // Throws std::logic_error when the asker did not declare `name` that way.
    const Subsystem* find(std::string_view name, bool needed) const;

    const SubsystemEntry& asker_;
    const std::vector<std::unique_ptr<Subsystem>>& subsystems_;
};

}  // namespace sim
