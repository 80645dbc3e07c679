// Writes the harbour level's glTF assets (one .gltf per asset, buffers embedded).
// Usage: make_assets [OUT_DIR]   (default: levels/harbour, relative to the working dir)
// Everything is built from code and a fixed hash, so reruns give the same files.
// Model space: metres, y up; vehicles face +x; origins at ground level unless noted.
// Colours are linear.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "tools/assets/AssetGeometry.h"
#include "tools/assets/GltfWriter.h"

namespace {

using namespace assets;
namespace fs = std::filesystem;
constexpr float kPi = glm::pi<float>();

namespace mat {
// A dielectric paint: a metallic share would tint the sky it reflects at grazing angles
// (the bonnet from the driver's seat) red, a pink glow.
const Material car_paint{"car_paint", {0.42f, 0.02f, 0.018f, 1}, 0.0f, 0.38f};
const Material glass{"glass", {0.035f, 0.05f, 0.065f, 1}, 0.0f, 0.05f};
const Material tyre{"tyre", {0.018f, 0.018f, 0.02f, 1}, 0.0f, 0.9f};
const Material chrome{"chrome", {0.6f, 0.6f, 0.62f, 1}, 0.9f, 0.25f};
const Material trim{"trim", {0.03f, 0.03f, 0.032f, 1}, 0.1f, 0.6f};
// The cabin's lining: under the roof it sees the sky only through the glass, and the
// renderer lights it so (its meshes "headliner", "sun_visors" and "pillars").
const Material headliner{"headliner", {0.8f, 0.78f, 0.74f, 1}, 0.0f, 0.95f};
const Material sun_visor{"sun_visor", {0.6f, 0.58f, 0.55f, 1}, 0.0f, 0.9f};
const Material pillar_lining{"pillar_lining", {0.42f, 0.41f, 0.39f, 1}, 0.0f, 0.9f};
const Material dashboard{"dashboard", {0.045f, 0.045f, 0.05f, 1}, 0.0f, 0.8f};
const Material instrument{"instrument", {0.85f, 0.85f, 0.82f, 1}, 0.0f, 0.5f};  // colours in COLOR_0
const Material needle{"needle", {0.9f, 0.25f, 0.03f, 1}, 0.0f, 0.4f, {0.12f, 0.03f, 0.0f}};  // lit from within
const Material mirror_glass{"mirror_glass", {0.85f, 0.86f, 0.88f, 1}, 1.0f, 0.06f};
const Material headlight{"headlight", {0.9f, 0.88f, 0.8f, 1}, 0.0f, 0.1f};
const Material taillight{"taillight", {0.45f, 0.01f, 0.01f, 1}, 0.0f, 0.2f};
const Material hull_white{"hull_white", {0.78f, 0.78f, 0.76f, 1}, 0.0f, 0.35f};
const Material hull_navy{"hull_navy", {0.01f, 0.018f, 0.07f, 1}, 0.0f, 0.4f};
const Material teak{"teak", {0.33f, 0.18f, 0.08f, 1}, 0.0f, 0.7f};
const Material siding{"corrugated_steel", {0.30f, 0.32f, 0.33f, 1}, 0.2f, 0.6f};
const Material roofing{"roofing", {0.12f, 0.13f, 0.14f, 1}, 0.2f, 0.7f};
const Material concrete{"concrete", {0.36f, 0.35f, 0.32f, 1}, 0.0f, 0.9f};
const Material pine{"pine", {0.50f, 0.32f, 0.15f, 1}, 0.0f, 0.8f};
const Material old_wood{"weathered_wood", {0.24f, 0.19f, 0.13f, 1}, 0.0f, 0.85f};
const Material tarred{"tarred_wood", {0.07f, 0.055f, 0.04f, 1}, 0.0f, 0.8f};
const Material steel{"painted_steel", {0.22f, 0.23f, 0.25f, 1}, 0.6f, 0.5f};
const Material tin{"tin", {0.55f, 0.55f, 0.57f, 1}, 0.8f, 0.35f};
const Material cardboard{"cardboard", {0.42f, 0.28f, 0.14f, 1}, 0.0f, 0.9f};
const Material rust{"rust", {1, 1, 1, 1}, 0.2f, 0.9f};  // colours in COLOR_0
const Material stone{"stone", {0.30f, 0.29f, 0.27f, 1}, 0.0f, 0.85f};
const Material cast_iron{"cast_iron", {0.03f, 0.03f, 0.03f, 1}, 0.5f, 0.6f};
const Material lamp_green{"lamp_green", {0.02f, 0.06f, 0.035f, 1}, 0.4f, 0.5f};
const Material lamp_glass{"lamp_glass", {1.0f, 0.85f, 0.55f, 1}, 0.0f, 0.2f};
const Material bark{"bark", {0.10f, 0.06f, 0.03f, 1}, 0.0f, 0.9f};
const Material needles{"needles", {0.02f, 0.08f, 0.025f, 1}, 0.0f, 0.85f};
const Material door_wood{"door_wood", {0.12f, 0.06f, 0.03f, 1}, 0.0f, 0.7f};
const Material barrel_blue{"barrel_blue", {0.025f, 0.07f, 0.22f, 1}, 0.3f, 0.6f};
}  // namespace mat

// Per-vertex rust: dark pits and a few patches of faded green paint.
vec4 rust_at(vec3 p) {
    float n = value_noise(p * 3.0f), d = value_noise(p * 11.0f + vec3(7.0f));
    vec3 c = glm::mix(vec3(0.07f, 0.03f, 0.015f), vec3(0.22f, 0.08f, 0.03f), n);
    if (value_noise(p * 1.3f + vec3(3.0f)) > 0.62f) c = glm::mix(c, vec3(0.09f, 0.15f, 0.11f), 0.8f);
    return vec4(c * (0.75f + 0.35f * d), 1.0f);
}

Asset car() {
    Asset a{"car", {}, {}};
    prism(a.part("body", mat::car_paint), {},
          {{-2.05f, 0.28f}, {2.05f, 0.28f}, {2.1f, 0.45f}, {2.05f, 0.72f}, {0.95f, 0.86f}, {-1.55f, 0.88f},
           {-2.08f, 0.8f}, {-2.1f, 0.45f}},
          -0.85f, 0.85f, flat());
    // The windshield's top edge lies well ahead of the driver's eye (-0.45, 1.2) so the
    // roof lining shows as a band at the top of the driver's view.
    const std::vector<vec2> cabin = {{-1.5f, 0.86f}, {0.9f, 0.86f}, {0.22f, 1.44f}, {-1.15f, 1.45f}};
    prism(a.part("cabin", mat::car_paint), {}, cabin, -0.78f, 0.78f, flat());
    // Windshield: the cabin's front slope, bowed forward a little across its width.
    Part& ws = a.part("windshield", mat::glass);
    vec2 lo = cabin[1], hi = cabin[2], slope_n = glm::normalize(vec2(hi.y - lo.y, lo.x - hi.x));
    const int segments = 6;
    const float half_w = 0.74f, bow = 0.05f;
    for (int i = 0; i <= segments; ++i) {
        float z = -half_w + 2.0f * half_w * float(i) / float(segments), k = z / half_w;
        float dx = bow * (1.0f - k * k), slope_dz = -2.0f * bow * k / half_w;
        vec3 n = glm::normalize(vec3(slope_n.x, slope_n.y, -slope_dz * slope_n.x));
        vec3 b(vec2(lo) + slope_n * 0.012f + vec2(dx, 0.0f), z), t(vec2(hi) + slope_n * 0.012f + vec2(dx * 0.6f, 0.0f), z);
        uint32_t vb = ws.v(b, n, vec4(1)), vt = ws.v(t, n, vec4(1));
        if (i > 0) ws.quad(vb - 2, vb, vt, vt - 2);
    }
    Part& win = a.part("windows", mat::glass);
    for (float side : {-1.0f, 1.0f})
        poly(win, {}, {{-1.35f, 0.93f, side * 0.785f}, {0.74f, 0.93f, side * 0.785f}, {0.24f, 1.38f, side * 0.785f},
                       {-1.1f, 1.39f, side * 0.785f}},
             {0, 0, side}, flat());
    vec2 rear_n = glm::normalize(vec2(cabin[3].y - cabin[0].y, cabin[0].x - cabin[3].x)) * -1.0f;
    poly(win, {}, {{-1.48f - 0.01f, 0.94f, -0.65f}, {-1.48f - 0.01f, 0.94f, 0.65f}, {-1.19f - 0.01f, 1.4f, 0.6f},
                   {-1.19f - 0.01f, 1.4f, -0.6f}},
         {rear_n.x, rear_n.y, 0}, flat());
    // The cabin seen from the driver's seat: a roof lining and A-pillars framing the
    // glass, the rear-view mirror, the dashboard with its speedometer, the steering wheel
    // and its wiper stalk. All sit inside the cabin's shell, so nothing changes outside.
    box(a.part("headliner", mat::headliner), {}, {-1.1f, 1.4f, -0.76f}, {0.2f, 1.415f, 0.76f}, flat());
    Part& visors = a.part("sun_visors", mat::sun_visor);  // folded up against the lining
    for (float side : {-1.0f, 1.0f})
        box(visors, {}, {0.0f, 1.388f, side < 0 ? -0.7f : 0.16f}, {0.17f, 1.4f, side < 0 ? -0.16f : 0.7f}, flat());
    Part& pillars = a.part("pillars", mat::pillar_lining);
    for (float side : {-1.0f, 1.0f}) {
        const vec2 in0 = -slope_n * 0.01f, in1 = -slope_n * 0.035f;
        prism(pillars, {}, {lo + in1, lo + in0, hi + in0, hi + in1}, side < 0 ? -0.775f : 0.73f,
              side < 0 ? -0.73f : 0.775f, flat());
    }
    // Frames facing the driver: local x is the car's right (+z), y up, z towards the seat.
    auto facing_driver = [](vec3 centre, float tilt) {  // tilt: the top leaning away, rad
        float s = std::sin(tilt), c = std::cos(tilt);
        return Xf{mat4(vec4(0, 0, 1, 0), vec4(s, c, 0, 0), vec4(-c, s, 0, 0), vec4(centre, 1))};
    };
    // Rear-view mirror: a rounded oblong on a stalk from the roof, its glass towards the seat.
    const std::vector<vec2> oblong = {{-0.12f, -0.016f}, {-0.106f, -0.033f}, {0.106f, -0.033f}, {0.12f, -0.016f},
                                      {0.12f, 0.016f},   {0.106f, 0.033f},   {-0.106f, 0.033f}, {-0.12f, 0.016f}};
    const Xf mirror_at = facing_driver({0.17f, 1.33f, 0.0f}, 0.0f);
    Part& mirror = a.part("mirror", mat::trim);
    box(mirror, {}, {0.17f, 1.35f, -0.012f}, {0.2f, 1.41f, 0.012f}, flat());
    prism(mirror, mirror_at, oblong, -0.03f, 0.0f, flat());
    std::vector<vec3> face;
    for (vec2 p : oblong) face.push_back(vec3(p * vec2(0.93f, 0.8f), 0.002f));
    poly(a.part("mirror_glass", mat::mirror_glass), mirror_at, face, {0, 0, 1}, flat());
    // Dashboard: under the windshield's foot, low enough that the bonnet still shows.
    // A floor over the body's top and door panels below the windows, so the seat sees
    // no paint from inside.
    Part& dash = a.part("dashboard", mat::dashboard);
    prism(dash, {}, {{0.3f, 0.3f}, {0.9f, 0.3f}, {0.9f, 0.86f}, {0.5f, 0.955f}, {0.3f, 0.965f}}, -0.8f, 0.8f, flat());
    for (float side : {-1.0f, 1.0f})
        box(dash, {}, {-1.5f, 0.3f, side < 0 ? -0.8f : 0.76f}, {0.9f, 0.93f, side < 0 ? -0.76f : 0.8f}, flat());
    box(dash, {}, {-1.5f, 0.88f, -0.76f}, {0.3f, 0.89f, 0.76f}, flat());  // the floor, over the body's top
    // Speedometer on the dashboard's face: a dark dial, 0 to 200 km/h over 270 degrees with
    // a tick every 20; the needle (drawn turned about the dial's centre by the renderer)
    // is modelled pointing straight up.
    const Xf dial = facing_driver({0.298f, 0.86f, 0.0f}, 0.0f);
    Part& face_part = a.part("speedo_dial", mat::instrument);
    ring_sector(face_part, dial, 0.0f, 0.072f, 0.0f, 2.0f * kPi, -0.004f, 0.0f, 24, flat(vec4(0.025f, 0.025f, 0.03f, 1)));
    ring_sector(face_part, dial, 0.072f, 0.08f, 0.0f, 2.0f * kPi, -0.004f, 0.006f, 24, flat(vec4(0.35f, 0.35f, 0.36f, 1)));
    for (int k = 0; k <= 10; ++k) {
        Xf tick = turned(dial, glm::radians(135.0f - 27.0f * float(k)), {0, 0, 1});
        float w = k % 5 == 0 ? 0.003f : 0.0018f;
        box(face_part, tick, {-w, 0.05f, 0.0f}, {w, 0.066f, 0.0015f}, flat());
    }
    box(a.part("speedo_needle", mat::needle), dial, {-0.0018f, -0.012f, 0.002f}, {0.0018f, 0.06f, 0.0035f}, flat());
    // Steering wheel: rim, three spokes and a hub, on a column tilted up towards the seat
    // (its top leaning 0.35 rad away); the renderer turns it and the stalk about that axis.
    const Xf wheel = facing_driver({0.02f, 0.88f, 0.0f}, 0.35f);
    Part& sw = a.part("steering_wheel", mat::trim);
    ring_sector(sw, wheel, 0.16f, 0.18f, 0.0f, 2.0f * kPi, -0.0125f, 0.0125f, 28, flat());
    box(sw, wheel, {-0.165f, -0.012f, -0.02f}, {0.165f, 0.012f, -0.006f}, flat());
    box(sw, wheel, {-0.014f, -0.165f, -0.02f}, {0.014f, 0.0f, -0.006f}, flat());
    box(sw, wheel, {-0.045f, -0.04f, -0.03f}, {0.045f, 0.035f, 0.01f}, flat());
    cylinder(a.part("steering_column", mat::dashboard), turned(wheel, kPi / 2.0f, {1, 0, 0}), 0.035f, 0.035f,
             -0.34f, -0.03f, 10, flat());
    box(a.part("wiper_stalk", mat::trim), wheel, {0.03f, -0.008f, -0.075f}, {0.16f, 0.008f, -0.06f}, flat());
    box(a.part("bumpers", mat::trim), {}, {2.02f, 0.3f, -0.86f}, {2.14f, 0.44f, 0.86f}, flat());
    box(a.parts.back(), {}, {-2.14f, 0.3f, -0.86f}, {-2.02f, 0.44f, 0.86f}, flat());
    Part& lights = a.part("headlights", mat::headlight);
    for (float z : {-0.62f, 0.62f}) box(lights, {}, {2.04f, 0.58f, z - 0.16f}, {2.1f, 0.68f, z + 0.16f}, flat());
    Part& tails = a.part("taillights", mat::taillight);
    for (float z : {-0.66f, 0.66f}) box(tails, {}, {-2.1f, 0.6f, z - 0.13f}, {-2.05f, 0.72f, z + 0.13f}, flat());
    // Wheels are nodes placed by translation; their geometry sits at the node origin.
    const char* names[4] = {"fl", "fr", "rl", "rr"};
    for (int i = 0; i < 4; ++i) {
        float x = i < 2 ? 1.35f : -1.35f, z = i % 2 ? 0.79f : -0.79f;
        Xf axle = turned({}, kPi / 2.0f, {1, 0, 0});  // local y -> z
        cylinder(a.part(std::string("wheel_") + names[i], mat::tyre, {x, 0.33f, z}), axle, 0.33f, 0.33f, -0.1f, 0.1f,
                 16, flat());
        float out = z > 0 ? 1.0f : -1.0f;  // the hubcap on the outer face
        cylinder(a.part(std::string("hubcap_") + names[i], mat::chrome, {x, 0.33f, z}), axle, 0.17f, 0.17f,
                 out > 0 ? 0.098f : -0.108f, out > 0 ? 0.108f : -0.098f, 12, flat());
    }
    return a;
}

Asset boat() {
    Asset a{"boat", {}, {}};
    // Hull from stations along x (transom at -3, stem at +3): half beam, keel, sheer.
    auto half_beam = [](float x) { float t = std::clamp((x + 0.6f) / 3.6f, 0.0f, 1.0f); return 1.2f * std::sqrt(1.0f - t * t); };
    auto keel = [](float x) { float t = std::clamp((x - 0.5f) / 2.5f, 0.0f, 1.0f); return -0.5f + 0.55f * t * t; };
    auto sheer = [](float x) { float t = std::clamp((x + 0.5f) / 3.5f, 0.0f, 1.0f); return 0.6f + 0.18f * t * t; };
    const float boot = 0.12f;  // waterline stripe: white topsides above, navy bottom below
    auto station = [](float u) { return -3.0f + 6.0f * std::sin(u * kPi / 2.0f); };  // denser at the bow
    auto bottom_at = [&](float x, float v) {  // half ellipse from port boot (v=0) over the keel to starboard
        float phi = (2.0f * v - 1.0f) * kPi / 2.0f;
        return vec3(x, boot + (keel(x) - boot) * std::cos(phi), half_beam(x) * std::sin(phi));
    };
    for (float side : {-1.0f, 1.0f})
        surface(a.part(side < 0 ? "hull_port" : "hull_starboard", mat::hull_white),
                [&](float u, float v) {  // topsides flare out a little towards the sheer
                    float x = station(u);
                    return vec3(x, boot + (sheer(x) - boot) * v, side * half_beam(x) * (1.0f + 0.08f * v));
                },
                20, 1, flat());
    surface(a.part("hull_bottom", mat::hull_navy), [&](float u, float v) { return bottom_at(station(u), v); }, 20, 8, flat());
    std::vector<vec3> transom = {{-3.0f, sheer(-3.0f), -half_beam(-3.0f) * 1.08f}};
    for (int j = 0; j <= 8; ++j) transom.push_back(bottom_at(-3.0f, float(j) / 8.0f));
    transom.emplace_back(-3.0f, sheer(-3.0f), half_beam(-3.0f) * 1.08f);
    poly(a.part("transom", mat::hull_white), {}, transom, {-1, 0, 0}, flat());
    surface(a.part("deck", mat::teak),
            [&](float u, float v) {
                float x = station(u);
                return vec3(x, sheer(x) - 0.05f, (2.0f * v - 1.0f) * std::max(half_beam(x) * 1.08f - 0.03f, 0.0f));
            },
            20, 1, flat());
    const std::vector<vec2> cabin = {{-1.7f, 0.5f}, {0.35f, 0.5f}, {0.05f, 1.35f}, {-1.6f, 1.4f}};
    prism(a.part("cabin", mat::hull_white), {}, cabin, -0.75f, 0.75f, flat());
    Part& win = a.part("windows", mat::glass);
    for (float side : {-1.0f, 1.0f})
        poly(win, {}, {{-1.45f, 0.95f, side * 0.755f}, {0.1f, 0.95f, side * 0.755f}, {-0.02f, 1.25f, side * 0.755f},
                       {-1.42f, 1.27f, side * 0.755f}},
             {0, 0, side}, flat());
    vec2 fn = glm::normalize(vec2(cabin[2].y - cabin[1].y, cabin[1].x - cabin[2].x));
    vec2 f0 = glm::mix(cabin[1], cabin[2], 0.35f) + fn * 0.012f, f1 = glm::mix(cabin[1], cabin[2], 0.85f) + fn * 0.012f;
    poly(win, {}, {{f0.x, f0.y, -0.6f}, {f0.x, f0.y, 0.6f}, {f1.x, f1.y, 0.55f}, {f1.x, f1.y, -0.55f}}, {fn.x, fn.y, 0}, flat());
    box(a.part("motor", mat::trim), {}, {-3.35f, -0.35f, -0.16f}, {-3.0f, 0.75f, 0.16f}, flat());
    // The helm on the cabin's roof (the helm view's eye is at (-0.6, 1.9, 0)): a console,
    // a wheel facing the helmsman and a low raked windscreen in a dark frame ahead of it.
    // Console and wheel stand to starboard and low, so the view over the bow stays open.
    box(a.part("helm_console", mat::hull_white), {}, {-0.15f, 1.36f, 0.2f}, {0.02f, 1.5f, 0.6f}, flat());
    {
        const float tilt = 0.5f, s = std::sin(tilt), c = std::cos(tilt);
        const Xf helm{mat4(vec4(0, 0, 1, 0), vec4(s, c, 0, 0), vec4(-c, s, 0, 0), vec4(-0.2f, 1.56f, 0.42f, 1))};
        Part& wheel = a.part("helm_wheel", mat::teak);
        ring_sector(wheel, helm, 0.17f, 0.195f, 0.0f, 2.0f * kPi, -0.012f, 0.012f, 24, flat());
        for (int k = 0; k < 3; ++k)
            box(wheel, turned(helm, 2.0f * kPi * float(k) / 3.0f, {0, 0, 1}), {-0.01f, 0.0f, -0.008f},
                {0.01f, 0.175f, 0.008f}, flat());
        cylinder(wheel, turned(helm, kPi / 2.0f, {1, 0, 0}), 0.03f, 0.03f, -0.06f, 0.02f, 10, flat());
    }
    const vec3 screen[4] = {{0.06f, 1.38f, -0.72f}, {0.06f, 1.38f, 0.72f}, {-0.08f, 1.72f, 0.66f}, {-0.08f, 1.72f, -0.66f}};
    const vec3 screen_n = glm::normalize(glm::cross(screen[1] - screen[0], screen[3] - screen[0]));
    poly(a.part("windscreen", mat::glass), {}, {screen[0], screen[1], screen[2], screen[3]},
         screen_n.x > 0.0f ? screen_n : -screen_n, flat());
    Part& frame = a.part("windscreen_frame", mat::trim);
    box(frame, {}, {-0.1f, 1.715f, -0.68f}, {-0.05f, 1.74f, 0.68f}, flat());
    for (float side : {-1.0f, 1.0f})
        prism(frame, {}, {{0.04f, 1.38f}, {0.08f, 1.38f}, {-0.06f, 1.74f}, {-0.1f, 1.74f}},
              side < 0 ? -0.74f : 0.66f, side < 0 ? -0.66f : 0.74f, flat());
    return a;
}

Asset warehouse() {
    Asset a{"warehouse", {}, {}};
    const float hx = 15.0f, hz = 10.0f, t = 0.3f, h = 7.0f;
    Shade grime = [](vec3 p) { return vec4(vec3(0.7f + 0.3f * std::min(p.y / 2.5f, 1.0f)), 1.0f); };
    // Each wall: a plain box, corrugated cladding outside. Walls are separate meshes
    // so each gets its own collision box and the hall stays hollow.
    auto wall = [&](const std::string& name, vec3 lo, vec3 hi, Xf clad, float c0, float c1, float y0, float y1) {
        Part& m = a.part(name, mat::siding);
        box(m, {}, lo, hi, grime);
        corrugated(m, clad, c0, c1, y0, y1, grime);
    };
    wall("wall_north", {-hx, 0, -hz}, {hx, h, -hz + t}, {glm::rotate(glm::translate(mat4(1), {0, 0, -hz - 0.02f}), kPi, {0, 1, 0})}, -hx, hx, 0, h);
    wall("wall_west", {-hx, 0, -hz + t}, {-hx + t, h, hz - t}, {glm::rotate(glm::translate(mat4(1), {-hx - 0.02f, 0, 0}), -kPi / 2, {0, 1, 0})}, -hz, hz, 0, h);
    wall("wall_east", {hx - t, 0, -hz + t}, {hx, h, hz - t}, {glm::rotate(glm::translate(mat4(1), {hx + 0.02f, 0, 0}), kPi / 2, {0, 1, 0})}, -hz, hz, 0, h);
    const float door_half = 4.0f, door_h = 5.0f;
    Xf south{glm::translate(mat4(1), {0, 0, hz + 0.02f})};
    wall("wall_south_west", {-hx, 0, hz - t}, {-door_half, h, hz}, south, -hx, -door_half, 0, h);
    wall("wall_south_east", {door_half, 0, hz - t}, {hx, h, hz}, south, door_half, hx, 0, h);
    wall("wall_south_lintel", {-door_half, door_h, hz - t}, {door_half, h, hz}, south, -door_half, door_half, door_h, h);
    box(a.part("roof", mat::roofing), {}, {-hx - 0.25f, h, -hz - 0.25f}, {hx + 0.25f, h + 0.2f, hz + 0.25f}, flat());
    // The floor slab is only a surface: no collision step at the door.
    Part& floor = a.part("nocollide_floor", mat::concrete);
    Shade stains = [](vec3 p) { return vec4(vec3(0.8f + 0.25f * value_noise(p * 0.6f)), 1.0f); };
    for (int i = 0; i < 6; ++i)
        for (int k = 0; k < 4; ++k) {
            float x0 = -hx + t + (2 * hx - 2 * t) * float(i) / 6.0f, x1 = -hx + t + (2 * hx - 2 * t) * float(i + 1) / 6.0f;
            float z0 = -hz + t + (2 * hz - 2 * t) * float(k) / 4.0f, z1 = -hz + t + (2 * hz - 2 * t) * float(k + 1) / 4.0f;
            poly(floor, {}, {{x0, 0.02f, z0}, {x1, 0.02f, z0}, {x1, 0.02f, z1}, {x0, 0.02f, z1}}, {0, 1, 0}, stains);
        }
    return a;
}

// Planked crate: each face in strips of varying tone, battens on the edges.
Asset crate(const std::string& name, float size, uint32_t seed) {
    Asset a{name, {}, {}};
    Part& m = a.part("crate", mat::pine);
    const int planks = size > 1.0f ? 6 : 4;
    float h = size / 2.0f;
    for (int axis = 0; axis < 3; ++axis)
        for (float sign : {-1.0f, 1.0f}) {
            int u = (axis + 1) % 3, v = (axis + 2) % 3;
            for (int k = 0; k < planks; ++k) {
                vec4 tone(0.78f + 0.3f * hash01(seed * 977u + uint32_t(axis * 100 + (sign > 0) * 50 + k)));
                tone.a = 1.0f;
                float v0 = -h + size * float(k) / float(planks), v1 = -h + size * float(k + 1) / float(planks);
                std::vector<vec3> pts;
                for (auto [uu, vv] : {std::pair{-h, v0}, {h, v0}, {h, v1}, {-h, v1}}) {
                    vec3 p(0.0f);
                    p[axis] = sign * h;
                    p[u] = uu;
                    p[v] = vv;
                    pts.push_back(p + vec3(0, h + 0.012f, 0));  // battens rest on the ground
                }
                vec3 n(0.0f);
                n[axis] = sign;
                poly(m, {}, pts, n, flat(tone));
            }
        }
    const float b = 0.06f, out = 0.012f;
    for (int axis = 0; axis < 3; ++axis)
        for (float s1 : {-1.0f, 1.0f})
            for (float s2 : {-1.0f, 1.0f}) {
                vec3 lo(0.0f), hi(0.0f);
                int u = (axis + 1) % 3, v = (axis + 2) % 3;
                lo[axis] = -h - out;
                hi[axis] = h + out;
                lo[u] = s1 * (h + out) - (s1 > 0 ? b : 0.0f);
                hi[u] = lo[u] + b;
                lo[v] = s2 * (h + out) - (s2 > 0 ? b : 0.0f);
                hi[v] = lo[v] + b;
                box(m, {}, lo + vec3(0, h + out, 0), hi + vec3(0, h + out, 0), flat(vec4(0.62f, 0.6f, 0.58f, 1)));
            }
    return a;
}

Asset shelf() {
    Asset a{"shelf", {}, {}};
    const float hw = 1.25f, hd = 0.3f, post = 0.05f;
    const float boards[3] = {0.25f, 0.95f, 1.65f};
    int n = 0;
    for (float x : {-hw, hw - post})
        for (float z : {-hd, hd - post})
            box(a.part("post_" + std::to_string(n++), mat::steel), {}, {x, 0, z}, {x + post, 2.0f, z + post}, flat());
    for (int i = 0; i < 3; ++i)
        box(a.part("board_" + std::to_string(i), mat::old_wood), {}, {-hw, boards[i], -hd}, {hw, boards[i] + 0.03f, hd},
            flat(vec4(0.85f + 0.2f * hash01(uint32_t(i) + 40u))));
    auto top = [&](int i) { return boards[i] + 0.03f; };
    Part& boxes0 = a.part("boxes_0", mat::cardboard);
    box(boxes0, at({-0.7f, top(0), 0}, 0.1f), {-0.25f, 0, -0.18f}, {0.25f, 0.38f, 0.18f}, flat());
    box(boxes0, at({0.15f, top(0), 0.02f}, -0.15f), {-0.3f, 0, -0.2f}, {0.3f, 0.3f, 0.2f}, flat(vec4(0.8f, 0.85f, 0.9f, 1)));
    Part& tins1 = a.part("tins_1", mat::tin);
    for (int k = 0; k < 5; ++k) cylinder(tins1, at({-0.9f + 0.22f * float(k), top(1), -0.05f}), 0.065f, 0.065f, 0, 0.13f, 12, flat());
    box(a.part("boxes_1", mat::cardboard), at({0.75f, top(1), 0}, 0.3f), {-0.2f, 0, -0.15f}, {0.2f, 0.25f, 0.15f}, flat());
    Part& tins2 = a.part("tins_2", mat::tin);
    for (int k = 0; k < 3; ++k) cylinder(tins2, at({0.3f + 0.25f * float(k), top(2), 0.05f}), 0.09f, 0.09f, 0, 0.2f, 12, flat());
    box(a.part("boxes_2", mat::cardboard), at({-0.6f, top(2), 0}, -0.05f), {-0.35f, 0, -0.2f}, {0.35f, 0.22f, 0.2f}, flat(vec4(0.9f, 0.9f, 0.8f, 1)));
    return a;
}

Asset old_car() {
    Asset a{"old_car", {}, {}};
    Shade rusty = [](vec3 p) { return rust_at(p); };
    // Subdivided boxes so the rust pattern has vertices to live on.
    auto rusty_box = [&](Part& m, vec3 lo, vec3 hi) {
        const float cell = 0.2f;
        for (int axis = 0; axis < 3; ++axis)
            for (float side : {0.0f, 1.0f}) {
                int u = (axis + 1) % 3, v = (axis + 2) % 3;
                int nu = std::max(1, int(std::ceil((hi[u] - lo[u]) / cell))), nv = std::max(1, int(std::ceil((hi[v] - lo[v]) / cell)));
                for (int i = 0; i < nu; ++i)
                    for (int k = 0; k < nv; ++k) {
                        auto corner = [&](int di, int dk) {
                            vec3 p(0.0f);
                            p[axis] = side > 0 ? hi[axis] : lo[axis];
                            p[u] = lo[u] + (hi[u] - lo[u]) * float(i + di) / float(nu);
                            p[v] = lo[v] + (hi[v] - lo[v]) * float(k + dk) / float(nv);
                            return p;
                        };
                        vec3 n(0.0f);
                        n[axis] = side > 0 ? 1.0f : -1.0f;
                        poly(m, {}, {corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)}, n, rusty);
                    }
            }
    };
    rusty_box(a.part("body", mat::rust), {-2.0f, 0.32f, -0.85f}, {2.0f, 0.92f, 0.85f});
    rusty_box(a.part("cabin", mat::rust), {-1.25f, 0.92f, -0.78f}, {0.55f, 1.5f, 0.78f});
    Part& bumpers = a.part("bumpers", mat::steel);
    for (float x : {-2.08f, 2.0f}) box(bumpers, {}, {x, 0.38f, -0.88f}, {x + 0.08f, 0.52f, 0.88f}, rusty);
    Part& win = a.part("windows", mat::glass);
    for (float side : {-1.0f, 1.0f}) poly(win, {}, {{-1.1f, 1.0f, side * 0.785f}, {0.4f, 1.0f, side * 0.785f}, {0.4f, 1.4f, side * 0.785f}, {-1.1f, 1.4f, side * 0.785f}}, {0, 0, side}, flat(vec4(0.6f, 0.6f, 0.55f, 1)));
    poly(win, {}, {{0.555f, 1.0f, -0.68f}, {0.555f, 1.0f, 0.68f}, {0.555f, 1.42f, 0.68f}, {0.555f, 1.42f, -0.68f}}, {1, 0, 0}, flat(vec4(0.6f, 0.6f, 0.55f, 1)));
    for (int i = 0; i < 4; ++i) {
        float x = i < 2 ? 1.38f : -1.38f, z = i % 2 ? 0.76f : -0.76f;
        // Flat tyres: sunk a few centimetres into the floor.
        cylinder(a.part("wheel_" + std::to_string(i), mat::tyre), turned(at({x, 0.28f, z}), kPi / 2, {1, 0, 0}), 0.32f, 0.32f, -0.1f, 0.1f, 14, flat(vec4(1.4f, 1.3f, 1.2f, 1)));
    }
    return a;
}

// A short concrete pipe on its side, in separate ring segments so the hollow stays open.
Asset pipe() {
    Asset a{"pipe", {}, {}};
    const int n = 12;
    Xf lying = turned(at({0, 0.7f, 0}), kPi / 2, {0, 1, 0});  // local z (the pipe axis) -> x
    Shade weathered = [](vec3 p) { return vec4(vec3(0.75f + 0.3f * value_noise(p * 4.0f)), 1.0f); };
    for (int i = 0; i < n; ++i)
        ring_sector(a.part("pipe_seg_" + std::to_string(i), mat::concrete), lying, 0.56f, 0.7f, 2 * kPi * float(i) / n,
                    2 * kPi * float(i + 1) / n, -1.0f, 1.0f, 2, weathered);
    return a;
}

// An open-top steel drum: staves around a bottom disc, hoops that do not collide.
Asset barrel() {
    Asset a{"barrel", {}, {}};
    const int n = 12;
    Xf upright = turned({}, -kPi / 2, {1, 0, 0});  // local z -> y
    Shade worn = [](vec3 p) { vec4 r = rust_at(p * 2.0f); return value_noise(p * 5.0f) > 0.7f ? r * 2.5f : vec4(1.0f); };
    for (int i = 0; i < n; ++i)
        ring_sector(a.part("stave_" + std::to_string(i), mat::barrel_blue), upright, 0.275f, 0.295f, 2 * kPi * float(i) / n,
                    2 * kPi * float(i + 1) / n, 0.0f, 0.88f, 2, worn);
    cylinder(a.part("bottom", mat::barrel_blue), {}, 0.28f, 0.28f, 0.0f, 0.02f, 16, worn);
    for (float y : {0.22f, 0.66f})
        cylinder(a.part(y < 0.5f ? "nocollide_hoop_lower" : "nocollide_hoop_upper", mat::barrel_blue), {}, 0.302f,
                 0.302f, y - 0.02f, y + 0.02f, 16, flat(vec4(0.7f, 0.7f, 0.7f, 1)), false);
    return a;
}

// Pier: deck x -4..4, z -21..21, top at y = 0, and tarred pilings down to y = -7.2.
Asset pier() {
    Asset a{"pier", {}, {}};
    Part& deck = a.part("deck", mat::old_wood);
    box(deck, {}, {-4, -0.4f, -21}, {4, 0, 21}, flat(vec4(0.6f, 0.6f, 0.6f, 1)), false);
    const int planks = 84;
    for (int k = 0; k < planks; ++k) {
        float z0 = -21.0f + 42.0f * float(k) / planks, z1 = -21.0f + 42.0f * float(k + 1) / planks;
        vec4 tone(0.75f + 0.35f * hash01(uint32_t(k) * 31u + 7u));
        tone.a = 1.0f;
        poly(deck, {}, {{-4, 0, z0}, {4, 0, z0}, {4, 0, z1}, {-4, 0, z1}}, {0, 1, 0}, flat(tone));
    }
    // Stringers under the deck edges carry the planks.
    for (float x : {-3.95f, 3.75f}) box(a.part(x < 0 ? "stringer_west" : "stringer_east", mat::tarred), {}, {x, -0.65f, -21}, {x + 0.2f, -0.4f, 21}, flat());
    int n = 0;
    for (float x : {-3.7f, 3.7f})
        for (int k = 0; k < 7; ++k)
            cylinder(a.part("piling_" + std::to_string(n++), mat::tarred), at({x, 0, -18.0f + 6.0f * float(k)}), 0.2f, 0.2f,
                     -7.2f, -0.4f, 8, flat());
    Part& cleats = a.part("nocollide_cleats", mat::cast_iron);
    for (float z : {-4.0f, 4.0f}) box(cleats, {}, {3.55f, 0, z - 0.2f}, {3.7f, 0.12f, z + 0.2f}, flat());
    return a;
}

Asset plinth() {
    Asset a{"tank_plinth", {}, {}};
    Part& m = a.part("plinth", mat::stone);
    box(m, {}, {-1, 0, -1}, {1, 0.24f, 1}, flat());
    box(m, {}, {-0.95f, 0.24f, -0.95f}, {0.95f, 0.3f, 0.95f}, flat(vec4(1.1f, 1.1f, 1.1f, 1)));
    return a;
}

// Lamp post: the arm reaches along +x to a head 6 m up.
Asset lamp_post() {
    Asset a{"lamp_post", {}, {}};
    Part& pole = a.part("pole", mat::lamp_green);
    cylinder(pole, {}, 0.13f, 0.1f, 0, 0.5f, 10, flat());
    cylinder(pole, {}, 0.07f, 0.06f, 0.5f, 6.0f, 10, flat());
    box(a.part("arm", mat::lamp_green), {}, {0, 5.86f, -0.04f}, {1.45f, 5.94f, 0.04f}, flat());
    box(a.part("head", mat::lamp_green), {}, {1.1f, 5.78f, -0.17f}, {1.75f, 5.96f, 0.17f}, flat());
    box(a.part("lamp", mat::lamp_glass), {}, {1.16f, 5.74f, -0.13f}, {1.69f, 5.78f, 0.13f}, flat());
    return a;
}

Asset bollard() {
    Asset a{"bollard", {}, {}};
    Part& m = a.part("bollard", mat::cast_iron);
    cylinder(m, {}, 0.15f, 0.13f, 0, 0.5f, 12, flat());
    cylinder(m, {}, 0.19f, 0.19f, 0.5f, 0.58f, 12, flat());
    cylinder(m, {}, 0.17f, 0.05f, 0.58f, 0.64f, 12, flat());
    return a;
}

// House: 8 m along x, 6 m deep, front (door) facing +z, pitched roof with its ridge along x.
Asset house(const std::string& name, vec4 wall, vec4 roof_colour, uint32_t seed) {
    Asset a{name, {}, {}};
    Material walls{"render", wall, 0.0f, 0.9f}, roof{"roof_tiles", roof_colour, 0.0f, 0.75f};
    Xf along_x = turned({}, kPi / 2, {0, 1, 0});  // prism axis (local z) -> x
    prism(a.part("walls", walls), along_x, {{3, -0.3f}, {3, 3}, {0, 4.6f}, {-3, 3}, {-3, -0.3f}}, -4, 4, flat());
    const float pitch = std::atan2(1.6f, 3.0f), run = 3.9f;
    for (float side : {-1.0f, 1.0f}) {
        Xf slab{glm::rotate(glm::translate(mat4(1), {0, 4.62f, 0}), side * pitch, {1, 0, 0})};
        box(a.part(side > 0 ? "roof_south" : "roof_north", roof), slab, {-4.3f, 0, side > 0 ? 0.0f : -run}, {4.3f, 0.12f, side > 0 ? run : 0.0f}, flat());
    }
    box(a.part("chimney", walls), {}, {1.8f, 3.6f, -1.4f}, {2.4f, 5.6f, -0.8f}, flat(vec4(0.8f, 0.8f, 0.8f, 1)));
    float door_x = hash01(seed) > 0.5f ? -2.0f : 1.2f;
    box(a.part("door", mat::door_wood), {}, {door_x, 0, 2.98f}, {door_x + 1.0f, 2.1f, 3.04f}, flat());
    Part& win = a.part("windows", mat::glass);
    for (float x : {-2.6f, -0.4f, 1.8f}) {
        if (std::fabs(x + 0.4f - (door_x + 0.5f)) < 1.0f) continue;
        box(win, {}, {x, 1.1f, 2.98f}, {x + 0.8f, 2.2f, 3.03f}, flat());
    }
    for (float x : {-2.2f, 1.0f}) box(win, {}, {x, 1.1f, -3.03f}, {x + 0.8f, 2.2f, -2.98f}, flat());
    return a;
}

// Pine: the trunk goes 1.5 m into the ground so a slope never shows its foot.
Asset tree() {
    Asset a{"pine", {}, {}};
    cylinder(a.part("trunk", mat::bark), {}, 0.2f, 0.14f, -1.5f, 2.6f, 8, flat());
    cylinder(a.part("nocollide_crown_lower", mat::needles), {}, 1.8f, 0.0f, 1.8f, 5.4f, 12, flat());
    cylinder(a.part("nocollide_crown_upper", mat::needles), {}, 1.25f, 0.0f, 3.9f, 7.0f, 12, flat(vec4(1.15f, 1.2f, 1.1f, 1)));
    return a;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc > 2 || (argc == 2 && argv[1][0] == '-')) {
        std::fprintf(stderr, "usage: make_assets [OUT_DIR]   (default levels/harbour)\n");
        return 2;
    }
    fs::path dir = argc == 2 ? fs::path(argv[1]) : fs::path("levels/harbour");
    try {
        fs::create_directories(dir);
        for (const Asset& a :
             {car(), boat(), warehouse(), crate("crate_large", 1.2f, 1), crate("crate_small", 0.8f, 2), shelf(),
              old_car(), pipe(), barrel(), pier(), plinth(), lamp_post(), bollard(),
              house("house_ochre", {0.58f, 0.36f, 0.12f, 1}, {0.36f, 0.08f, 0.04f, 1}, 1),
              house("house_blue", {0.32f, 0.46f, 0.58f, 1}, {0.07f, 0.075f, 0.085f, 1}, 2),
              house("house_white", {0.68f, 0.64f, 0.56f, 1}, {0.25f, 0.06f, 0.03f, 1}, 3), tree()})
            write_gltf(a, dir);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "make_assets: %s\n", e.what());
        return 1;
    }
    return 0;
}
