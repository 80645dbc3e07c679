// tinygltf is compiled here, once, without image support (the assets have none).
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include "tools/assets/GltfWriter.h"

#include <cstdio>
#include <stdexcept>

namespace assets {

namespace fs = std::filesystem;


void write_gltf(const Asset& asset, const fs::path& dir) {
    tinygltf::Model m;
    m.asset.version = "2.0";
    m.asset.generator = "spindrift make_assets";
    for (const Material& mt : asset.materials) {
        tinygltf::Material t;
        t.name = mt.name;
        t.pbrMetallicRoughness.baseColorFactor = {mt.color.r, mt.color.g, mt.color.b, mt.color.a};
        t.pbrMetallicRoughness.metallicFactor = mt.metallic;
        t.pbrMetallicRoughness.roughnessFactor = mt.roughness;
        t.emissiveFactor = {mt.emissive.r, mt.emissive.g, mt.emissive.b};
        m.materials.push_back(t);
    }
    tinygltf::Buffer buffer;
    auto view = [&](const void* data, size_t bytes, int target) {
        buffer.data.resize((buffer.data.size() + 3) & ~size_t(3), 0);  // 4-byte alignment
        tinygltf::BufferView v;
        v.buffer = 0;
        v.byteOffset = buffer.data.size();
        v.byteLength = bytes;
        v.target = target;
        auto* p = static_cast<const unsigned char*>(data);
        buffer.data.insert(buffer.data.end(), p, p + bytes);
        m.bufferViews.push_back(v);
        return int(m.bufferViews.size() - 1);
    };
    auto accessor = [&](int v, int component, int type, size_t count, bool normalized) {
        tinygltf::Accessor acc;
        acc.bufferView = v;
        acc.componentType = component;
        acc.type = type;
        acc.count = count;
        acc.normalized = normalized;
        m.accessors.push_back(acc);
        return int(m.accessors.size() - 1);
    };
    tinygltf::Node root;
    root.name = asset.name;
    for (const Part& p : asset.parts) {
        tinygltf::Primitive prim;
        prim.mode = TINYGLTF_MODE_TRIANGLES;
        prim.material = p.material;
        prim.attributes["POSITION"] = accessor(view(p.pos.data(), p.pos.size() * 12, TINYGLTF_TARGET_ARRAY_BUFFER),
                                               TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, p.pos.size(), false);
        vec3 lo = p.pos[0], hi = p.pos[0];
        for (vec3 q : p.pos) lo = glm::min(lo, q), hi = glm::max(hi, q);
        m.accessors.back().minValues = {lo.x, lo.y, lo.z};
        m.accessors.back().maxValues = {hi.x, hi.y, hi.z};
        prim.attributes["NORMAL"] = accessor(view(p.nrm.data(), p.nrm.size() * 12, TINYGLTF_TARGET_ARRAY_BUFFER),
                                             TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, p.nrm.size(), false);
        if (std::any_of(p.col.begin(), p.col.end(), [](vec4 c) { return c != vec4(1.0f); })) {
            std::vector<uint8_t> rgba;  // normalised u8: linear colours, 4 bytes a vertex
            for (vec4 c : p.col)
                for (int k = 0; k < 4; ++k) rgba.push_back(uint8_t(std::lround(c[k] * 255.0f)));
            prim.attributes["COLOR_0"] = accessor(view(rgba.data(), rgba.size(), TINYGLTF_TARGET_ARRAY_BUFFER),
                                                  TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_TYPE_VEC4, p.col.size(), true);
        }
        if (p.pos.size() <= 65535) {
            std::vector<uint16_t> small(p.idx.begin(), p.idx.end());
            prim.indices = accessor(view(small.data(), small.size() * 2, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                                    TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR, small.size(), false);
        } else {
            prim.indices = accessor(view(p.idx.data(), p.idx.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                                    TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, p.idx.size(), false);
        }
        tinygltf::Mesh mesh;
        mesh.name = p.name;
        mesh.primitives.push_back(prim);
        m.meshes.push_back(mesh);
        tinygltf::Node node;
        node.name = p.name;
        node.mesh = int(m.meshes.size() - 1);
        if (p.translation != vec3(0.0f)) node.translation = {p.translation.x, p.translation.y, p.translation.z};
        m.nodes.push_back(node);
        root.children.push_back(int(m.nodes.size() - 1));
    }
    buffer.data.resize((buffer.data.size() + 3) & ~size_t(3), 0);
    m.buffers.push_back(buffer);
    m.nodes.push_back(root);
    tinygltf::Scene scene;
    scene.name = asset.name;
    scene.nodes.push_back(int(m.nodes.size() - 1));
    m.scenes.push_back(scene);
    m.defaultScene = 0;
    fs::path file = dir / (asset.name + ".gltf");
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToFile(&m, file.string(), true, true, true, false))
        throw std::runtime_error("cannot write " + file.string());
    size_t vertices = 0;
    for (const Part& p : asset.parts) vertices += p.pos.size();
    std::printf("%-28s %3zu meshes %6zu vertices %8ju bytes\n", file.string().c_str(), asset.parts.size(), vertices,
                uintmax_t(fs::file_size(file)));
}

}  // namespace assets
