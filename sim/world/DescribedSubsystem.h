#pragma once
// A subsystem whose hash, save and restore all walk its one description of its state:
// `template <class Archive> void describe(Archive& ar)` (sim/core/StateArchive.h).
#include "sim/core/StateArchive.h"
#include "sim/world/Subsystem.h"

namespace sim {

template <class Derived> class DescribedSubsystem : public Subsystem {
public:
    uint64_t hash() const final { return hash_state(self()); }
    void save(StateWriter& out) const final { out.nested(self()); }
    void restore(StateReader& in) final { in.nested(static_cast<Derived&>(*this)); }

private:
    const Derived& self() const { return static_cast<const Derived&>(*this); }
};

}  // namespace sim
