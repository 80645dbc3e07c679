// The world assembled from a list of subsystem entries: the declared reads are checked
// when it is assembled, a world of just a few subsystems steps, and the list's order is
// the stepping order.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ErrorMessage.h"
#include "SimTestLevel.h"
#include "sim/water/WaterSim.h"
#include "sim/world/World.h"

namespace {

// Records the names of the subsystems in the order the world steps them.
class StepOrder : public sim::StepObserver {
public:
    explicit StepOrder(const sim::World& world) : world_(world) {}
    void before(size_t i) override { names.emplace_back(world_.subsystems()[i]->name()); }
    void after(size_t) override {}
    std::vector<std::string> names;

private:
    const sim::World& world_;
};

std::vector<std::string> names_of(const std::vector<sim::SubsystemEntry>& list) {
    std::vector<std::string> names;
    for (const sim::SubsystemEntry& e : list) names.emplace_back(e.name);
    return names;
}

}  // namespace

TEST(WorldAssembly, AMissingDependencyIsRefusedNamingBoth) {
    const std::string message = message_of<std::invalid_argument>(
        [] { sim::World world(make_test_level(), sim::standard_subsystems({"car", "camera"})); });
    EXPECT_EQ(message, "subsystem 'car' reads 'player', which this world does not have");
}

TEST(WorldAssembly, AReadTheEntryDoesNotDeclareIsRefused) {
    std::vector<sim::SubsystemEntry> list = sim::standard_subsystems({"player", "car", "boat"});
    sim::entry_named(list, "car").reads.clear();  // the car reads the player all the same
    const std::string message = message_of<std::logic_error>([&] { sim::World world(make_test_level(), list); });
    EXPECT_NE(message.find("subsystem 'car' reads 'player' without declaring it"), std::string::npos) << message;
}

TEST(WorldAssembly, AnUnknownNameIsRefusedWithTheListsNames) {
    const std::string message = message_of<std::invalid_argument>([] { sim::standard_subsystems({"waves"}); });
    EXPECT_NE(message.find("no subsystem 'waves'"), std::string::npos) << message;
    EXPECT_NE(message.find("water"), std::string::npos) << message;
}

TEST(WorldAssembly, AWorldOfJustTheTerrainAndTheWaterSteps) {
    sim::LevelDesc level = make_test_level();
    level.water.enabled = true;  // 128 m of grid from the origin: the sea beyond the shore
    sim::World world(level, sim::standard_subsystems({"water"}));
    ASSERT_EQ(world.subsystem_names(), std::vector<std::string>{"water"});
    const sim::WaterSim& water = world.get<sim::WaterSim>();
    EXPECT_EQ(&world.sea(), static_cast<const sim::SeaSurface*>(&water)) << "the water is the sea boats would ride";

    const glm::vec2 centre{60.0f, 60.0f}, beside{63.0f, 60.0f};
    world.get<sim::WaterSim>().disturb(centre, 1.0f, 0.3f);
    const uint64_t still = world.hash().world;
    for (int t = 0; t < 60; ++t) world.step({});
    EXPECT_EQ(world.tick(), 60u);
    EXPECT_NE(world.hash().world, still);
    EXPECT_GT(std::abs(world.sea().height_at(beside) - level.sea_level_m), 1e-4f) << "the push spread as waves";
}

TEST(WorldAssembly, TheGameWorldStepsInTheListsOrder) {
    sim::LevelDesc level = make_test_level();
    level.water.enabled = true;
    sim::World world(level);
    StepOrder order(world);
    world.step({}, &order);
    // The test level has no dust, rain glass, tank or objectives.
    const std::vector<std::string> expected{"player", "weather", "car", "boat", "weapon", "objects", "water", "camera"};
    EXPECT_EQ(order.names, expected);
    EXPECT_EQ(world.subsystem_names(), expected);
}

TEST(WorldAssembly, AListInAnotherOrderIsSteppedInThatOrder) {
    std::vector<sim::SubsystemEntry> list = sim::standard_subsystems({"player", "car", "boat", "camera"});
    std::swap(list[0], list[3]);  // the camera first, the player last
    sim::World world(make_test_level(), list);
    StepOrder order(world);
    world.step({}, &order);
    EXPECT_EQ(order.names, names_of(list));
    EXPECT_EQ(order.names, (std::vector<std::string>{"camera", "car", "boat", "player"}));
}
