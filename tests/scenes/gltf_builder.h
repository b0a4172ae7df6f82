#pragma once
// Writes tiny glTF files for loader tests: buffers are built in memory and embedded as base64
// data URIs (or written next to the file), JSON is assembled with nlohmann::json.

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

namespace cavewall::scenes::testing {

inline std::string base64(const std::vector<std::uint8_t>& data) {
    static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < data.size(); i += 3) {
        const std::uint32_t n =
            (data[i] << 16) | ((i + 1 < data.size() ? data[i + 1] : 0) << 8) | (i + 2 < data.size() ? data[i + 2] : 0);
        out += k[(n >> 18) & 63];
        out += k[(n >> 12) & 63];
        out += i + 1 < data.size() ? k[(n >> 6) & 63] : '=';
        out += i + 2 < data.size() ? k[n & 63] : '=';
    }
    return out;
}

// The folder for files written by tests (CAVEWALL_TEST_OUTPUT from ctest, else the build dir).
inline std::filesystem::path testOutput(const std::string& sub) {
    const char* env = std::getenv("CAVEWALL_TEST_OUTPUT");
    std::filesystem::path dir = std::filesystem::path(env ? env : CAVEWALL_BINARY_DIR "/test-output") / sub;
    std::filesystem::create_directories(dir);
    return dir;
}

struct GltfBuilder {
    std::vector<std::uint8_t> bin;
    nlohmann::json j = {{"asset", {{"version", "2.0"}}},
                        {"bufferViews", nlohmann::json::array()},
                        {"accessors", nlohmann::json::array()},
                        {"meshes", nlohmann::json::array()},
                        {"nodes", nlohmann::json::array()}};

    int addView(const void* data, std::size_t bytes, int stride = 0) {
        while (bin.size() % 4) bin.push_back(0);
        nlohmann::json v = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes}};
        if (stride) v["byteStride"] = stride;
        const auto* p = static_cast<const std::uint8_t*>(data);
        bin.insert(bin.end(), p, p + bytes);
        j["bufferViews"].push_back(v);
        return static_cast<int>(j["bufferViews"].size()) - 1;
    }
    int addAccessor(int view, int componentType, std::size_t count, const char* type, std::size_t offset = 0,
                    bool normalized = false) {
        nlohmann::json a = {{"componentType", componentType}, {"count", count}, {"type", type}};
        if (view >= 0) a["bufferView"] = view;
        if (offset) a["byteOffset"] = offset;
        if (normalized) a["normalized"] = true;
        j["accessors"].push_back(a);
        return static_cast<int>(j["accessors"].size()) - 1;
    }
    int addFloats(const std::vector<float>& v, const char* type, int components) {
        return addAccessor(addView(v.data(), v.size() * 4), 5126, v.size() / components, type);
    }
    template <class T>
    int addIndices(const std::vector<T>& v) {
        const int ct = sizeof(T) == 1 ? 5121 : sizeof(T) == 2 ? 5123 : 5125;
        return addAccessor(addView(v.data(), v.size() * sizeof(T)), ct, v.size(), "SCALAR");
    }
    // A mesh with one primitive; returns the mesh index.
    int addMesh(nlohmann::json primitive) {
        j["meshes"].push_back({{"primitives", nlohmann::json::array({primitive})}});
        return static_cast<int>(j["meshes"].size()) - 1;
    }
    int addNode(nlohmann::json node) {
        j["nodes"].push_back(node);
        return static_cast<int>(j["nodes"].size()) - 1;
    }
    // Puts every node without a parent into scene 0 and embeds the buffer.
    std::string text(bool embed = true, const std::string& binUri = "") {
        nlohmann::json out = j;
        std::vector<bool> child(out["nodes"].size(), false);
        for (auto& n : out["nodes"])
            if (n.contains("children"))
                for (auto& c : n["children"])
                    if (c.get<std::size_t>() < child.size()) child[c.get<std::size_t>()] = true;
        nlohmann::json roots = nlohmann::json::array();
        for (std::size_t i = 0; i < child.size(); ++i)
            if (!child[i]) roots.push_back(i);
        if (!out.contains("scenes")) out["scenes"] = {{{"nodes", roots}}};
        const std::string uri = embed ? "data:application/octet-stream;base64," + base64(bin) : binUri;
        if (!out.contains("buffers")) out["buffers"] = {{{"byteLength", bin.size()}, {"uri", uri}}};
        return out.dump();
    }
    // Written atomically (a file of this process's own, renamed over `name`): ctest runs tests
    // in parallel processes, and tests that share a file (every SceneDescription test writes
    // ../description/model.gltf) write the same bytes, so a reader sees one whole file or the
    // other, never one being rewritten. Throws std::runtime_error when it cannot be written.
    std::filesystem::path write(const std::string& name, bool embed = true, const std::string& binUri = "") {
        const auto file = testOutput("gltf") / name;
        const std::filesystem::path temp = file.string() + ".tmp" + std::to_string(::getpid());
        {
            std::ofstream out(temp, std::ios::binary);
            out << text(embed, binUri);
            out.close();
            if (!out) throw std::runtime_error(temp.string() + ": cannot write");
        }
        std::filesystem::rename(temp, file);
        return file;
    }
};

// A unit right triangle in z = 0 (counter-clockwise from +Z) as a complete one-node file.
inline GltfBuilder triangleFile() {
    GltfBuilder b;
    const int pos = b.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
    const int mesh = b.addMesh({{"attributes", {{"POSITION", pos}}}});
    b.addNode({{"mesh", mesh}});
    return b;
}

}  // namespace cavewall::scenes::testing
