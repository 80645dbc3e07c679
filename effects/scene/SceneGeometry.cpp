#include "effects/scene/SceneGeometry.h"

#include <algorithm>
#include <string>
#include <tuple>

#include <glm/common.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include "effects/scene/CabinInstruments.h"
#include "effects/scene/SceneLighting.h"  // kSkyMapSize
#include "effects/scene/TerrainMesh.h"

namespace effects {

namespace {
constexpr int kMaxRoads = 16;  // size of u_roads in mesh.frag.glsl

// A model whose every mesh gives off `emissive` (HDR radiance) on top of its shading.
Model glowing(Model m, glm::vec3 emissive) {
    for (MeshData& mesh : m.meshes) mesh.emissive = emissive;
    return m;
}

std::vector<OpenSky::Box> prop_boxes(const SceneDesc& desc) {
    std::vector<OpenSky::Box> boxes;
    for (const PropInstance& p : desc.props) boxes.push_back(world_box(desc.models[size_t(p.model)], p.transform));
    return boxes;
}

// The boxes' bounds (zero without any).
OpenSky::Box bounds(const std::vector<OpenSky::Box>& boxes) {
    OpenSky::Box b{glm::vec3(0.0f), glm::vec3(0.0f)};
    for (size_t i = 0; i < boxes.size(); ++i) {
        b.first = i == 0 ? boxes[i].first : glm::min(b.first, boxes[i].first);
        b.second = i == 0 ? boxes[i].second : glm::max(b.second, boxes[i].second);
    }
    return b;
}

// The ground, its triangles with no prop above them apart (the sky-occlusion map's).
TerrainMesh ground_mesh(const sim::Terrain& terrain, const SceneDesc& desc) {
    TerrainMesh mesh = make_terrain_mesh(terrain, 2.0f);
    std::vector<OpenSky::Box> props = prop_boxes(desc);
    const OpenSky::Box b = bounds(props);
    split_open_sky(mesh, OpenSky(std::move(props), b.first, b.second, kSkyMapSize));
    return mesh;
}

// The model matrix, and the normal matrix once per draw on the CPU, not per vertex on the GPU.
void place(const gl::Program& p, const glm::mat4& model, bool depth_only) {
    p.set("u_model", model);
    if (!depth_only) p.set("u_normal_matrix", glm::mat3(glm::transpose(glm::inverse(model))));
}
}  // namespace

std::pair<glm::vec3, glm::vec3> world_box(const Model& m, const glm::mat4& transform) {
    glm::vec3 lo(0.0f), hi(0.0f);
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 corner(c & 1 ? m.bounds_max.x : m.bounds_min.x, c & 2 ? m.bounds_max.y : m.bounds_min.y,
                               c & 4 ? m.bounds_max.z : m.bounds_min.z);
        const glm::vec3 p(transform * glm::vec4(corner, 1.0f));
        lo = c == 0 ? p : glm::min(lo, p);
        hi = c == 0 ? p : glm::max(hi, p);
    }
    return {lo, hi};
}

SceneGeometry::SceneGeometry(const SceneDesc& desc, const sim::Terrain& terrain)
    : desc_(desc),
      level_(terrain.level()),
      terrain_(ground_mesh(terrain, desc)),
      sea_(make_sea_model(terrain.level().sea_level_m, 3000.0f)),
      sphere_(make_sphere_model(12, 20)),
      box_(make_box_model()),
      next_box_(glowing(make_box_model(), glm::vec3(1.8f, 0.55f, 0.05f))),
      hit_sphere_(glowing(make_sphere_model(12, 20), glm::vec3(0.2f, 1.4f, 0.3f))),
      batches_(desc) {
    for (const Model& m : desc.models) models_.push_back(std::make_unique<GpuModel>(m));
    std::tie(props_min_, props_max_) = bounds(prop_boxes(desc));
}

int SceneGeometry::ground_road_count() const { return std::min<int>(int(level_.roads.size()), kMaxRoads); }

void SceneGeometry::apply_ground(const gl::Program& p) const {
    const int n = ground_road_count();
    for (int i = 0; i < n; ++i) {
        const sim::Rect& r = level_.roads[size_t(i)];
        p.set("u_roads[" + std::to_string(i) + "]", glm::vec4(r.min.x, r.min.y, r.max.x, r.max.y));
    }
    p.set("u_shore_z", level_.shore_z_m);
    p.set("u_sea_level", level_.sea_level_m);
}

void SceneGeometry::draw_props(const gl::Program& p, bool depth_only) const {
    for (const PropInstance& inst : desc_.props) {
        place(p, inst.transform, depth_only);
        models_[size_t(inst.model)]->draw(p, depth_only);
    }
}

void SceneGeometry::draw_vehicle(const gl::Program& p, sim::Vehicle vehicle, const sim::Pose& pose) const {
    const int model = vehicle == sim::Vehicle::Car ? desc_.car_model : desc_.boat_model;
    if (model < 0) return;
    p.use();
    place(p, pose.matrix(), false);
    models_[size_t(model)]->draw(p, false);
}

void SceneGeometry::draw(const gl::Program& p, const gl::Program& ground, const FramePoses& poses, Use use,
                         const Frustum& view, const Select& select, Car car, const std::optional<glm::vec3>& eye,
                         const gl::Program* open_sky_ground) const {
    const bool depth_only = use != Use::Shading;
    auto material = [&](glm::vec4 tint) {
        if (!depth_only) p.set("u_tint", tint);
    };
    p.use();
    material(glm::vec4(1.0f));
    if (use != Use::StillShadowCasters) draw_moving(p, poses, depth_only, view, select, car, eye);
    if (use == Use::MovingShadowCasters) return;
    material(glm::vec4(1.0f));
    batches_.draw(p, depth_only, view, select, eye);

    if (open_sky_ground) place(*open_sky_ground, glm::mat4(1.0f), depth_only);
    ground.use();
    place(ground, glm::mat4(1.0f), depth_only);
    // A level stretch of ground shades nothing: a ray rising from anything above the
    // ground towards the sun can only meet the ground where it rises. Left out of
    // the shadow map, it saves the raster of most of the map and cannot self-shadow.
    terrain_.draw(ground, depth_only, view, depth_only, select, open_sky_ground);
}

void SceneGeometry::plan_terrain(glm::vec3 eye, float pixels_per_radian) {
    // Half a scene pixel: where the frame is enlarged (the auto scale's floor is about a
    // third of the output), a pixel's error would be a step of three.
    if (terrain_.plan(eye, pixels_per_radian, 0.5f)) ++terrain_generation_;
}

std::vector<std::pair<glm::vec3, glm::vec3>> SceneGeometry::moving_caster_boxes(const FramePoses& poses) const {
    std::vector<std::pair<glm::vec3, glm::vec3>> boxes;
    constexpr float kTurningParts_m = 0.5f;  // wheels steered and spun past the model's bounds at rest
    for (const auto& [model, pose] : {std::pair{desc_.car_model, poses.car}, std::pair{desc_.boat_model, poses.boat}})
        if (model >= 0) {
            const auto [lo, hi] = world_box(desc_.models[size_t(model)], pose.matrix());
            boxes.emplace_back(lo - kTurningParts_m, hi + kTurningParts_m);
        }
    for (const FramePoses::Object& o : poses.objects) boxes.emplace_back(o.position - o.radius_m, o.position + o.radius_m);
    for (const ObjectiveMarker& m : poses.markers) boxes.emplace_back(m.lo, m.hi);
    return boxes;
}

void SceneGeometry::draw_moving(const gl::Program& p, const FramePoses& poses, bool depth_only,
                                const Frustum& view, const Select& select, Car car,
                                const std::optional<glm::vec3>& eye) const {
    auto selected = [&](const Model& m, const glm::mat4& transform) {
        if (!select) return true;
        const auto [lo, hi] = world_box(m, transform);
        return select(lo, hi);
    };
    auto material = [&](glm::vec4 tint) {
        if (!depth_only) p.set("u_tint", tint);
    };
    // The cabin's lining sees the sky only through the glass: mesh.frag.glsl's u_cabin_lining.
    // The eye in a vehicle's model space, for its parts' order.
    auto eye_in = [&](const glm::mat4& transform) -> std::optional<glm::vec3> {
        if (!eye) return std::nullopt;
        return glm::vec3(glm::inverse(transform) * glm::vec4(*eye, 1.0f));
    };
    auto lining = [&](const std::string& mesh) {
        if (!depth_only) p.set("u_cabin_lining", mesh == "headliner" || mesh == "sun_visors" || mesh == "pillars" ? 1.0f : 0.0f);
    };
    if (desc_.car_model >= 0 && car == Car::Drawn && selected(desc_.models[size_t(desc_.car_model)], poses.car.matrix())) {
        // Wheels and hubcaps (meshes "wheel_fl", "hubcap_rr", ...) turn
        // about their axle (model z) and the front ones steer about their vertical. In the
        // cabin the needle turns about the dial's centre and the wiper stalk about the
        // steering wheel's (each modelled after the part it turns about).
        const glm::mat4 body = poses.car.matrix();
        auto turned_about = [&](glm::vec3 pivot, float angle, glm::vec3 axis) {
            return glm::translate(glm::rotate(glm::translate(body, pivot), angle, axis), -pivot);
        };
        const GpuModel& car_model = *models_[size_t(desc_.car_model)];
        const glm::vec3 dial_centre = car_model.part_centre("speedo_dial"), wheel_centre = car_model.part_centre("steering_wheel");
        car_model.draw_parts(p, depth_only, [&](const std::string& mesh, glm::vec3 centre) {
            lining(mesh);
            if (mesh == "speedo_needle")
                return place(p, turned_about(dial_centre, cabin::speedo_needle_rad(poses.car_speed_mps), cabin::dial_axis()), depth_only);
            if (mesh == "steering_wheel")
                return place(p, turned_about(centre, cabin::steering_wheel_rad(poses.car_steer_rad), cabin::column_axis()), depth_only);
            if (mesh == "wiper_stalk")
                return place(p, turned_about(wheel_centre, cabin::wiper_stalk_rad(poses.wipers), cabin::column_axis()), depth_only);
            const bool wheel = mesh.starts_with("wheel_") || mesh.starts_with("hubcap_");
            if (!wheel) return place(p, body, depth_only);
            const bool front = mesh.size() >= 2 && mesh[mesh.size() - 2] == 'f';
            glm::mat4 m = glm::translate(body, centre);
            if (front) m = glm::rotate(m, poses.car_steer_rad, glm::vec3(0.0f, 1.0f, 0.0f));
            m = glm::rotate(m, -poses.car_wheel_spin_rad, glm::vec3(0.0f, 0.0f, 1.0f));  // rolling forward
            place(p, glm::translate(m, -centre), depth_only);
        }, eye_in(body));
        lining("");
    }
    if (desc_.boat_model >= 0 && selected(desc_.models[size_t(desc_.boat_model)], poses.boat.matrix())) {
        // The helm's wheel turns about its hub with the steering.
        const glm::mat4 hull = poses.boat.matrix();
        models_[size_t(desc_.boat_model)]->draw_parts(p, depth_only, [&](const std::string& mesh, glm::vec3 centre) {
            if (mesh != "helm_wheel") return place(p, hull, depth_only);
            const glm::mat4 m = glm::rotate(glm::translate(hull, centre), cabin::helm_wheel_rad(poses.boat_steer),
                                            cabin::helm_axis());
            place(p, glm::translate(m, -centre), depth_only);
        }, eye_in(hull));
    }
    for (const FramePoses::Object& o : poses.objects) {
        const glm::vec3 lo = o.position - o.radius_m, hi = o.position + o.radius_m;
        if (view.outside(lo, hi) || (select && !select(lo, hi))) continue;
        // Stones grey, floats bright orange so they read on the water.
        material(o.sinks ? glm::vec4(0.18f, 0.18f, 0.17f, 1.0f) : glm::vec4(0.9f, 0.28f, 0.04f, 1.0f));
        glm::mat4 m = glm::translate(glm::mat4(1.0f), o.position) * glm::scale(glm::mat4(1.0f), glm::vec3(o.radius_m));
        place(p, m, depth_only);
        sphere_.draw(p, depth_only);
    }
    draw_markers(p, poses, depth_only, view, select);
}

void SceneGeometry::draw_markers(const gl::Program& p, const FramePoses& poses, bool depth_only, const Frustum& view,
                                 const Select& select) const {
    for (const ObjectiveMarker& m : poses.markers) {
        if (view.outside(m.lo, m.hi) || (select && !select(m.lo, m.hi))) continue;
        if (!depth_only) p.set("u_tint", m.tint);
        place(p, m.transform, depth_only);
        const bool ball = m.shape == ObjectiveMarker::Shape::Ball;
        if (ball) (m.glow == ObjectiveMarker::Glow::Hit ? hit_sphere_ : sphere_).draw(p, depth_only);
        else (m.glow == ObjectiveMarker::Glow::Next ? next_box_ : box_).draw(p, depth_only);
    }
    if (!depth_only) p.set("u_tint", glm::vec4(1.0f));
}

}  // namespace effects
