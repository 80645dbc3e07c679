// tinygltf's implementation lives in this translation unit. Its stb image codecs are
// left out: level models carry no textures (images are skipped), and leaving them out
// keeps an image decoder away from untrusted files and stb off the include path.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include "game/level/GltfModel.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/vector_relational.hpp>

#include "sim/core/Hash.h"

namespace game {

namespace fs = std::filesystem;

std::string read_level_file(const fs::path& file, uint64_t max_bytes) {
    std::error_code ec;
    if (!fs::exists(file, ec)) throw LevelError(file.string() + ": not found");
    if (!fs::is_regular_file(file, ec)) throw LevelError(file.string() + ": not a regular file");
    uint64_t size = fs::file_size(file, ec);
    if (ec) throw LevelError(file.string() + ": cannot read its size: " + ec.message());
    if (size > max_bytes)
        throw LevelError(file.string() + ": too large (" + std::to_string(size) + " bytes, at most " +
                         std::to_string(max_bytes) + ")");
    std::ifstream in(file, std::ios::binary);
    std::string bytes(size, '\0');
    if (!in || !in.read(bytes.data(), std::streamsize(size)) || in.gcount() != std::streamsize(size))
        throw LevelError(file.string() + ": cannot be read");
    return bytes;
}

size_t json_nesting_depth(std::string_view text) {
    size_t depth = 0, deepest = 0;
    bool in_string = false, escaped = false;
    for (char c : text) {
        if (in_string) {
            if (escaped) escaped = false;
            else if (c == '\\') escaped = true;
            else if (c == '"') in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return deepest;
}

namespace {

void hash_blob(sim::Hasher* content, const void* data, size_t n) {
    if (!content) return;
    content->u64(n);
    content->bytes(data, n);
}

// Filesystem callbacks for external buffers: the same size limit as the file itself,
// no path expansion, no writing, and their bytes go into the content hash.
bool file_exists(const std::string& path, void*) {
    std::error_code ec;
    return fs::is_regular_file(path, ec);
}
std::string keep_path(const std::string& path, void*) { return path; }
bool read_external(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    try {
        std::string bytes = read_level_file(path, kMaxGltfFileBytes);
        hash_blob(static_cast<sim::Hasher*>(user), bytes.data(), bytes.size());
        out->assign(bytes.begin(), bytes.end());
        return true;
    } catch (const LevelError& e) {
        if (err) *err += e.what();
        return false;
    }
}
bool refuse_write(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "writing is not allowed while loading";
    return false;
}
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int,
                void*) {
    return true;  // textures are not used
}

std::string trim(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
    for (char& c : s)
        if (c == '\n') c = ';';
    return s;
}

tinygltf::Model parse_gltf(const std::string& bytes, const fs::path& file, sim::Hasher* content) {
    // The JSON part: all of a .gltf, or a .glb's first chunk (its header says how long).
    std::string_view json_text = bytes;
    bool binary = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0;
    if (binary) {
        uint32_t chunk = 0;
        if (bytes.size() >= 20) std::memcpy(&chunk, bytes.data() + 12, 4);
        json_text = std::string_view(bytes).substr(std::min<size_t>(20, bytes.size()), chunk);
    }
    if (json_nesting_depth(json_text) > kMaxJsonNesting)
        throw LevelError(file.string() + ": invalid glTF: JSON nested deeper than " + std::to_string(kMaxJsonNesting) +
                         " levels");
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({&file_exists, &keep_path, &read_external, &refuse_write, content});
    loader.SetImageLoader(&skip_image, nullptr);
    tinygltf::Model model;
    std::string err, warn, base = file.parent_path().string();
    bool ok = false;
    try {
        if (binary)
            ok = loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                             unsigned(bytes.size()), base);
        else
            ok = loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), base);
    } catch (const std::exception& e) {
        ok = false;
        err = e.what();
    }
    if (!ok) throw LevelError(file.string() + ": invalid glTF: " + (err.empty() ? "unknown error" : trim(err)));
    return model;
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// One accessor, checked to lie inside its buffer: every element can be read safely.
struct AccessorView {
    const unsigned char* data = nullptr;
    size_t stride = 0, count = 0, component_bytes = 0;
    int components = 0, component_type = 0;
    bool normalized = false;

    float component(size_t i, int c) const {
        const unsigned char* p = data + i * stride + size_t(c) * component_bytes;
        switch (component_type) {
            case TINYGLTF_COMPONENT_TYPE_FLOAT: {
                float f;
                std::memcpy(&f, p, 4);
                return f;
            }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return float(p[0]) / 255.0f;
            default: {
                uint16_t u;
                std::memcpy(&u, p, 2);
                return float(u) / 65535.0f;
            }
        }
    }
    uint32_t index(size_t i) const {
        const unsigned char* p = data + i * stride;
        if (component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) return p[0];
        if (component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
            uint16_t u;
            std::memcpy(&u, p, 2);
            return u;
        }
        uint32_t u;
        std::memcpy(&u, p, 4);
        return u;
    }
};

class Flattener {
public:
    Flattener(const tinygltf::Model& gltf, const fs::path& file) : gltf_(gltf), file_(file) {}

    effects::Model run() {
        const tinygltf::Scene& scene = pick_scene();
        std::vector<bool> seen(gltf_.nodes.size(), false);
        std::vector<std::pair<int, glm::mat4>> stack;
        for (auto it = scene.nodes.rbegin(); it != scene.nodes.rend(); ++it) stack.emplace_back(*it, glm::mat4(1.0f));
        while (!stack.empty()) {
            auto [index, parent] = stack.back();
            stack.pop_back();
            if (index < 0 || size_t(index) >= gltf_.nodes.size())
                fail("the scene refers to node " + std::to_string(index) + ", which does not exist");
            if (seen[size_t(index)])
                fail("node " + std::to_string(index) + " is reached twice (a cycle or a shared child)");
            seen[size_t(index)] = true;
            const tinygltf::Node& node = gltf_.nodes[size_t(index)];
            glm::mat4 world = parent * local_transform(node, index);
            if (node.mesh >= 0) add_mesh(node, index, world);
            for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) stack.emplace_back(*it, world);
        }
        if (model_.meshes.empty()) fail("the default scene has no triangles");
        bool first = true;
        for (const effects::MeshData& m : model_.meshes)
            for (const effects::MeshVertex& v : m.vertices) {
                model_.bounds_min = first ? v.position : glm::min(model_.bounds_min, v.position);
                model_.bounds_max = first ? v.position : glm::max(model_.bounds_max, v.position);
                first = false;
            }
        model_.name = file_.stem().string();
        return std::move(model_);
    }

private:
    [[noreturn]] void fail(const std::string& what) const { throw LevelError(file_.string() + ": " + what); }

    const tinygltf::Scene& pick_scene() const {
        if (gltf_.scenes.empty()) fail("no scenes");
        int s = gltf_.defaultScene >= 0 ? gltf_.defaultScene : 0;
        if (size_t(s) >= gltf_.scenes.size()) fail("default scene " + std::to_string(s) + " does not exist");
        return gltf_.scenes[size_t(s)];
    }

    glm::mat4 local_transform(const tinygltf::Node& node, int index) const {
        std::string where = "node " + std::to_string(index) + ": ";
        glm::mat4 m(1.0f);
        if (!node.matrix.empty()) {
            if (node.matrix.size() != 16) fail(where + "matrix must have 16 numbers");
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) m[c][r] = float(node.matrix[size_t(c * 4 + r)]);  // column-major
        } else {
            const auto& t = node.translation;
            const auto& r = node.rotation;
            const auto& s = node.scale;
            if (!t.empty() && t.size() != 3) fail(where + "translation must have 3 numbers");
            if (!r.empty() && r.size() != 4) fail(where + "rotation must have 4 numbers");
            if (!s.empty() && s.size() != 3) fail(where + "scale must have 3 numbers");
            glm::mat4 tm(1.0f), rm(1.0f), sm(1.0f);
            if (!t.empty()) tm[3] = glm::vec4(float(t[0]), float(t[1]), float(t[2]), 1.0f);
            if (!r.empty()) {
                glm::quat q{float(r[3]), float(r[0]), float(r[1]), float(r[2])};  // glTF stores x, y, z, w
                float len = glm::length(q);
                if (!(len > 1e-6f) || !std::isfinite(len)) fail(where + "rotation is not a unit quaternion");
                rm = glm::mat4_cast(q / len);
            }
            if (!s.empty()) sm = glm::mat4(glm::vec4(float(s[0]), 0, 0, 0), glm::vec4(0, float(s[1]), 0, 0),
                                           glm::vec4(0, 0, float(s[2]), 0), glm::vec4(0, 0, 0, 1));
            m = tm * rm * sm;
        }
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                if (!std::isfinite(m[c][r])) fail(where + "transform is not finite");
        return m;
    }

    AccessorView view(int accessor, const std::string& what) const {
        std::string where = what + " (accessor " + std::to_string(accessor) + "): ";
        if (accessor < 0 || size_t(accessor) >= gltf_.accessors.size()) fail(where + "accessor does not exist");
        const tinygltf::Accessor& a = gltf_.accessors[size_t(accessor)];
        if (a.sparse.isSparse) fail(where + "sparse accessors are not supported");
        if (a.bufferView < 0 || size_t(a.bufferView) >= gltf_.bufferViews.size())
            fail(where + "has no valid bufferView");
        const tinygltf::BufferView& bv = gltf_.bufferViews[size_t(a.bufferView)];
        if (bv.buffer < 0 || size_t(bv.buffer) >= gltf_.buffers.size()) fail(where + "its bufferView has no valid buffer");
        const std::vector<unsigned char>& buf = gltf_.buffers[size_t(bv.buffer)].data;
        if (bv.byteOffset > buf.size() || bv.byteLength > buf.size() - bv.byteOffset)
            fail(where + "bufferView " + std::to_string(a.bufferView) + " lies outside its buffer (" +
                 std::to_string(bv.byteOffset) + " + " + std::to_string(bv.byteLength) + " bytes of " +
                 std::to_string(buf.size()) + ")");
        AccessorView v;
        switch (a.componentType) {
            case TINYGLTF_COMPONENT_TYPE_BYTE:
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: v.component_bytes = 1; break;
            case TINYGLTF_COMPONENT_TYPE_SHORT:
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: v.component_bytes = 2; break;
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            case TINYGLTF_COMPONENT_TYPE_FLOAT: v.component_bytes = 4; break;
            default: fail(where + "unknown componentType " + std::to_string(a.componentType));
        }
        switch (a.type) {
            case TINYGLTF_TYPE_SCALAR: v.components = 1; break;
            case TINYGLTF_TYPE_VEC2: v.components = 2; break;
            case TINYGLTF_TYPE_VEC3: v.components = 3; break;
            case TINYGLTF_TYPE_VEC4: v.components = 4; break;
            default: fail(where + "matrix or unknown accessor types are not supported here");
        }
        if (a.count == 0) fail(where + "count is 0");
        if (a.count > 3 * kMaxGltfVertices) fail(where + "count " + std::to_string(a.count) + " is too large");
        size_t element = v.component_bytes * size_t(v.components);
        v.stride = bv.byteStride ? bv.byteStride : element;
        if (v.stride < element) fail(where + "byteStride is smaller than one element");
        uint64_t needed = uint64_t(a.count - 1) * v.stride + element;  // counts are bounded: no overflow
        if (a.byteOffset > bv.byteLength || needed > bv.byteLength - a.byteOffset)
            fail(where + "reads outside its bufferView " + std::to_string(a.bufferView) + " (needs " +
                 std::to_string(needed) + " bytes from offset " + std::to_string(a.byteOffset) + ", the view has " +
                 std::to_string(bv.byteLength) + ")");
        v.data = buf.data() + bv.byteOffset + a.byteOffset;
        v.count = a.count;
        v.component_type = a.componentType;
        v.normalized = a.normalized;
        return v;
    }

    void add_mesh(const tinygltf::Node& node, int node_index, const glm::mat4& world) {
        if (size_t(node.mesh) >= gltf_.meshes.size())
            fail("node " + std::to_string(node_index) + " refers to mesh " + std::to_string(node.mesh) +
                 ", which does not exist");
        const tinygltf::Mesh& mesh = gltf_.meshes[size_t(node.mesh)];
        std::string name = !node.name.empty() ? node.name
                           : !mesh.name.empty() ? mesh.name
                                                : "node" + std::to_string(node_index);
        for (size_t p = 0; p < mesh.primitives.size(); ++p)
            add_primitive(mesh.primitives[p], name, world,
                          "mesh '" + mesh.name + "' (node '" + name + "') primitive " + std::to_string(p));
    }

    void add_primitive(const tinygltf::Primitive& prim, const std::string& name, const glm::mat4& world,
                       const std::string& what) {
        if (prim.mode != -1 && prim.mode != TINYGLTF_MODE_TRIANGLES)
            fail(what + ": mode " + std::to_string(prim.mode) + " is not supported (triangles only)");
        auto attribute = [&](const char* key) {
            auto it = prim.attributes.find(key);
            return it == prim.attributes.end() ? -1 : it->second;
        };
        int pos_index = attribute("POSITION");
        if (pos_index < 0) fail(what + ": has no POSITION");
        AccessorView pos = view(pos_index, what + " POSITION");
        if (pos.components != 3 || pos.component_type != TINYGLTF_COMPONENT_TYPE_FLOAT)
            fail(what + " POSITION: must be a float VEC3");
        if (pos.count > kMaxGltfVertices - vertex_total_)
            fail("more than " + std::to_string(kMaxGltfVertices) + " vertices");
        vertex_total_ += pos.count;

        std::optional<AccessorView> nrm, col;
        if (int n = attribute("NORMAL"); n >= 0) {
            nrm = view(n, what + " NORMAL");
            if (nrm->components != 3 || nrm->component_type != TINYGLTF_COMPONENT_TYPE_FLOAT)
                fail(what + " NORMAL: must be a float VEC3");
            if (nrm->count != pos.count) fail(what + " NORMAL: count differs from POSITION's");
        }
        if (int c = attribute("COLOR_0"); c >= 0) {
            col = view(c, what + " COLOR_0");
            bool is_float = col->component_type == TINYGLTF_COMPONENT_TYPE_FLOAT;
            bool is_unorm = col->normalized && (col->component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                                col->component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
            if ((col->components != 3 && col->components != 4) || !(is_float || is_unorm))
                fail(what + " COLOR_0: must be VEC3/VEC4 of floats or normalised u8/u16");
            if (col->count != pos.count) fail(what + " COLOR_0: count differs from POSITION's");
        }

        effects::MeshData mesh;
        mesh.name = name;
        glm::vec4 base(1.0f);
        mesh.metallic = 1.0f;  // glTF's default material
        mesh.roughness = 1.0f;
        if (prim.material >= 0) {
            if (size_t(prim.material) >= gltf_.materials.size())
                fail(what + ": material " + std::to_string(prim.material) + " does not exist");
            const auto& pbr = gltf_.materials[size_t(prim.material)].pbrMetallicRoughness;
            if (pbr.baseColorFactor.size() != 4) fail(what + ": baseColorFactor must have 4 numbers");
            base = glm::vec4(float(pbr.baseColorFactor[0]), float(pbr.baseColorFactor[1]),
                             float(pbr.baseColorFactor[2]), float(pbr.baseColorFactor[3]));
            mesh.metallic = float(pbr.metallicFactor);
            mesh.roughness = float(pbr.roughnessFactor);
            const std::vector<double>& emissive = gltf_.materials[size_t(prim.material)].emissiveFactor;
            if (emissive.size() != 3) fail(what + ": emissiveFactor must have 3 numbers");
            mesh.emissive = glm::vec3(float(emissive[0]), float(emissive[1]), float(emissive[2]));
            if (!std::isfinite(base.x + base.y + base.z + base.w) || !std::isfinite(mesh.metallic) ||
                !std::isfinite(mesh.roughness) || !std::isfinite(mesh.emissive.x + mesh.emissive.y + mesh.emissive.z))
                fail(what + ": material factors are not finite");
            if (glm::any(glm::lessThan(mesh.emissive, glm::vec3(0.0f)))) fail(what + ": emissiveFactor is negative");
            mesh.metallic = std::clamp(mesh.metallic, 0.0f, 1.0f);
            mesh.roughness = std::clamp(mesh.roughness, 0.0f, 1.0f);
        }

        glm::mat3 linear(world);
        float det = glm::determinant(linear);
        // Cofactor matrix = det * inverse-transpose: defined even for a singular scale;
        // the sign keeps normals pointing out of mirrored geometry.
        glm::mat3 normal_matrix(glm::cross(linear[1], linear[2]), glm::cross(linear[2], linear[0]),
                                glm::cross(linear[0], linear[1]));
        if (det < 0.0f) normal_matrix = -normal_matrix;

        mesh.vertices.resize(pos.count);
        for (size_t i = 0; i < pos.count; ++i) {
            effects::MeshVertex& v = mesh.vertices[i];
            glm::vec3 p(pos.component(i, 0), pos.component(i, 1), pos.component(i, 2));
            v.position = glm::vec3(world * glm::vec4(p, 1.0f));
            if (!finite(v.position)) fail(what + " POSITION: vertex " + std::to_string(i) + " is not finite");
            if (nrm) {
                glm::vec3 n = normal_matrix * glm::vec3(nrm->component(i, 0), nrm->component(i, 1), nrm->component(i, 2));
                float len = glm::length(n);
                if (!std::isfinite(len)) fail(what + " NORMAL: vertex " + std::to_string(i) + " is not finite");
                v.normal = len > 1e-12f ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);
            }
            glm::vec4 c(1.0f);
            if (col) {
                for (int k = 0; k < col->components; ++k) c[k] = col->component(i, k);
                if (!std::isfinite(c.x + c.y + c.z + c.w))
                    fail(what + " COLOR_0: vertex " + std::to_string(i) + " is not finite");
            }
            v.color = base * c;
        }

        if (prim.indices >= 0) {
            AccessorView idx = view(prim.indices, what + " indices");
            if (idx.components != 1 || idx.normalized ||
                (idx.component_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                 idx.component_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                 idx.component_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
                fail(what + " indices: must be SCALAR u8/u16/u32");
            if (idx.count % 3 != 0) fail(what + " indices: count " + std::to_string(idx.count) + " is not a multiple of 3");
            mesh.indices.resize(idx.count);
            for (size_t i = 0; i < idx.count; ++i) {
                uint32_t k = idx.index(i);
                if (k >= pos.count)
                    fail(what + " indices: index " + std::to_string(k) + " at " + std::to_string(i) +
                         " is out of range (" + std::to_string(pos.count) + " vertices)");
                mesh.indices[i] = k;
            }
        } else {
            if (pos.count % 3 != 0)
                fail(what + ": " + std::to_string(pos.count) + " unindexed vertices is not a multiple of 3");
            mesh.indices.resize(pos.count);
            for (size_t i = 0; i < pos.count; ++i) mesh.indices[i] = uint32_t(i);
        }
        if (det < 0.0f)  // a mirroring transform turns the winding inside out
            for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
        if (!nrm) compute_normals(mesh);
        model_.meshes.push_back(std::move(mesh));
    }

    // Area-weighted vertex normals: flat where vertices are not shared, smooth where they are.
    static void compute_normals(effects::MeshData& mesh) {
        std::vector<glm::vec3> sum(mesh.vertices.size(), glm::vec3(0.0f));
        for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
            glm::vec3 n = glm::cross(mesh.vertices[b].position - mesh.vertices[a].position,
                                     mesh.vertices[c].position - mesh.vertices[a].position);
            sum[a] += n;
            sum[b] += n;
            sum[c] += n;
        }
        for (size_t i = 0; i < sum.size(); ++i) {
            float len = glm::length(sum[i]);
            mesh.vertices[i].normal = len > 1e-20f && std::isfinite(len) ? sum[i] / len : glm::vec3(0.0f, 1.0f, 0.0f);
        }
    }

    const tinygltf::Model& gltf_;
    const fs::path& file_;
    effects::Model model_;
    size_t vertex_total_ = 0;
};

}  // namespace

effects::Model load_gltf_model(const fs::path& file, sim::Hasher* content) {
    std::string bytes = read_level_file(file, kMaxGltfFileBytes);
    hash_blob(content, bytes.data(), bytes.size());
    return parse_gltf_model(bytes, file, content);
}

effects::Model parse_gltf_model(const std::string& bytes, const fs::path& file, sim::Hasher* content) {
    if (bytes.size() > kMaxGltfFileBytes)
        throw LevelError(file.string() + ": too large (" + std::to_string(bytes.size()) + " bytes, at most " +
                         std::to_string(kMaxGltfFileBytes) + ")");
    tinygltf::Model gltf = parse_gltf(bytes, file, content);
    return Flattener(gltf, file).run();
}

}  // namespace game
