#include "scenes/gltf_meshopt.h"

#include "config/error.h"

#include <meshoptimizer.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <climits>
#include <cstdio>
#include <set>

namespace cavewall::scenes {
namespace {

using Json = nlohmann::json;
constexpr const char* kMeshoptExt = "EXT_meshopt_compression";

// File text quoted in a message, cut short: a hostile file may put megabytes there.
std::string quoted(std::string text) {
    if (text.size() > 40) text = text.substr(0, 40) + "...";
    return text;
}

// A JSON value as text (invalid UTF-8 replaced), cut short.
std::string quoted(const Json& value) { return quoted(value.dump(-1, ' ', false, Json::error_handler_t::replace)); }

[[noreturn]] void fail(const std::string& file, const std::string& where, const std::string& what) {
    throw Error(file + ": " + where + ": " + what);
}

std::uint64_t unsignedField(const Json& e, const char* key, bool required, const std::string& where,
                            const std::string& file) {
    const auto it = e.find(key);
    if (it == e.end()) {
        if (required) fail(file, where + "." + key, "missing (expected a non-negative integer)");
        return 0;
    }
    if (!it->is_number_unsigned() && !(it->is_number_integer() && it->get<std::int64_t>() >= 0))
        fail(file, where + "." + key, "expected a non-negative integer, got " + quoted(*it));
    return it->get<std::uint64_t>();
}

std::string stringField(const Json& e, const char* key, const char* fallback, const std::string& where,
                        const std::string& file) {
    const auto it = e.find(key);
    if (it == e.end()) return fallback;
    if (!it->is_string()) fail(file, where + "." + key, "expected a string, got " + quoted(*it));
    return it->get<std::string>();
}

MeshoptMode parseMode(const std::string& s, const std::string& where, const std::string& file) {
    if (s == "ATTRIBUTES") return MeshoptMode::Attributes;
    if (s == "TRIANGLES") return MeshoptMode::Triangles;
    if (s == "INDICES") return MeshoptMode::Indices;
    fail(file, where, "unknown mode '" + quoted(s) + "' (expected ATTRIBUTES, TRIANGLES or INDICES)");
}

MeshoptFilter parseFilter(const std::string& s, const std::string& where, const std::string& file) {
    if (s == "NONE") return MeshoptFilter::None;
    if (s == "OCTAHEDRAL") return MeshoptFilter::Octahedral;
    if (s == "QUATERNION") return MeshoptFilter::Quaternion;
    if (s == "EXPONENTIAL") return MeshoptFilter::Exponential;
    fail(file, where, "unknown filter '" + quoted(s) + "' (expected NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL)");
}

// The extension's rules on byteStride and count per mode and filter; meshoptimizer asserts
// them, so they are checked before any decoder runs.
void checkLayout(const MeshoptView& v, const std::string& where, const std::string& file) {
    const std::uint64_t s = v.byteStride;
    const std::string got = ", got " + std::to_string(s);
    if (v.mode == MeshoptMode::Attributes && (s == 0 || s % 4 != 0 || s > 256))
        fail(file, where + ".byteStride", "expected a multiple of 4 from 4 to 256 for mode ATTRIBUTES" + got);
    if (v.mode != MeshoptMode::Attributes) {
        if (s != 2 && s != 4) fail(file, where + ".byteStride", "expected 2 or 4 for index data" + got);
        if (v.filter != MeshoptFilter::None)
            fail(file, where + ".filter", "index data takes no filter (expected NONE or no filter)");
    }
    if (v.mode == MeshoptMode::Triangles && v.count % 3 != 0)
        fail(file, where + ".count", "expected a multiple of 3 for mode TRIANGLES, got " + std::to_string(v.count));
    if (v.filter == MeshoptFilter::Octahedral && s != 4 && s != 8)
        fail(file, where + ".byteStride", "expected 4 or 8 for filter OCTAHEDRAL" + got);
    if (v.filter == MeshoptFilter::Quaternion && s != 8)
        fail(file, where + ".byteStride", "expected 8 for filter QUATERNION" + got);
    if (v.count > UINT64_MAX / std::max<std::uint64_t>(s, 1))
        fail(file, where + ".count", "byteStride x count overflows (got " + std::to_string(v.count) + " elements)");
}

std::string decodeFailure(int rc, const unsigned char* src, std::uint64_t size) {
    char header[8] = "none";
    if (size > 0) std::snprintf(header, sizeof header, "0x%02X", src[0]);
    if (rc == -1)
        return std::string("unsupported bitstream version (header byte ") + header +
               "; expected a version this meshoptimizer reads)";
    return "the compressed bytes are malformed or do not hold byteStride x count (meshoptimizer returned " +
           std::to_string(rc) + ", expected 0)";
}

// Checks `v` against its bufferView and buffers; returns the decoded size.
std::uint64_t checkAgainstModel(const tinygltf::Model& model, const MeshoptView& v, const std::vector<int>& fallbacks,
                                const std::string& file) {
    const std::string bw = "bufferViews[" + std::to_string(v.view) + "]";
    const std::string where = bw + ".extensions." + kMeshoptExt;
    if (static_cast<std::size_t>(v.view) >= model.bufferViews.size())
        fail(file, bw, "out of range (expected < " + std::to_string(model.bufferViews.size()) + " buffer views)");
    const tinygltf::BufferView& parent = model.bufferViews[v.view];
    const std::uint64_t decoded = v.byteStride * v.count;
    if (parent.byteLength != decoded)
        fail(file, bw + ".byteLength",
             std::to_string(parent.byteLength) +
                 " does not match the compressed view (expected byteStride x count = " + std::to_string(v.byteStride) +
                 " x " + std::to_string(v.count) + " = " + std::to_string(decoded) + ")");
    if (parent.byteStride != 0 && parent.byteStride != v.byteStride)
        fail(file, bw + ".byteStride",
             std::to_string(parent.byteStride) + " differs from the extension's (expected " +
                 std::to_string(v.byteStride) + ")");
    if (static_cast<std::size_t>(v.buffer) >= model.buffers.size())
        fail(file, where + ".buffer",
             "buffer " + std::to_string(v.buffer) + " is out of range (expected < " +
                 std::to_string(model.buffers.size()) + " buffers)");
    if (std::binary_search(fallbacks.begin(), fallbacks.end(), v.buffer))
        fail(file, where + ".buffer",
             "buffer " + std::to_string(v.buffer) + " is a fallback buffer (expected the buffer of compressed bytes)");
    const std::uint64_t size = model.buffers[v.buffer].data.size();
    if (v.byteOffset > size || v.byteLength > size - v.byteOffset)
        fail(file, where,
             "byte range " + std::to_string(v.byteOffset) + " + " + std::to_string(v.byteLength) + " exceeds buffer " +
                 std::to_string(v.buffer) + " (expected at most " + std::to_string(size) + " bytes)");
    if (decoded / kMaxMeshoptExpansion > v.byteLength)
        fail(file, where,
             std::to_string(v.byteLength) + " compressed bytes cannot hold " + std::to_string(decoded) +
                 " decoded bytes (expected at most " + std::to_string(kMaxMeshoptExpansion) + " per compressed byte)");
    return decoded;
}

void decodeOne(const MeshoptView& v, const unsigned char* src, unsigned char* dst, const std::string& file) {
    if (v.count == 0) return;
    const auto count = static_cast<std::size_t>(v.count), stride = static_cast<std::size_t>(v.byteStride),
               size = static_cast<std::size_t>(v.byteLength);
    int rc = 0;
    switch (v.mode) {
        case MeshoptMode::Attributes: rc = meshopt_decodeVertexBuffer(dst, count, stride, src, size); break;
        case MeshoptMode::Triangles: rc = meshopt_decodeIndexBuffer(dst, count, stride, src, size); break;
        case MeshoptMode::Indices: rc = meshopt_decodeIndexSequence(dst, count, stride, src, size); break;
    }
    if (rc != 0)
        fail(file, "bufferViews[" + std::to_string(v.view) + "].extensions." + kMeshoptExt,
             decodeFailure(rc, src, size));
    switch (v.filter) {
        case MeshoptFilter::None: break;
        case MeshoptFilter::Octahedral: meshopt_decodeFilterOct(dst, count, stride); break;
        case MeshoptFilter::Quaternion: meshopt_decodeFilterQuat(dst, count, stride); break;
        case MeshoptFilter::Exponential: meshopt_decodeFilterExp(dst, count, stride); break;
    }
}

}  // namespace

std::vector<MeshoptView> readMeshoptViews(const nlohmann::json& doc, const std::string& file) {
    std::vector<MeshoptView> views;
    const auto list = doc.find("bufferViews");
    if (list == doc.end() || !list->is_array()) return views;
    for (std::size_t i = 0; i < list->size() && i <= INT_MAX; ++i) {
        const Json& bv = (*list)[i];
        if (!bv.is_object() || !bv.contains("extensions") || !bv["extensions"].is_object()) continue;
        const auto e = bv["extensions"].find(kMeshoptExt);
        if (e == bv["extensions"].end()) continue;
        const std::string where = "bufferViews[" + std::to_string(i) + "].extensions." + kMeshoptExt;
        if (!e->is_object()) fail(file, where, "expected an object, got " + quoted(*e));
        MeshoptView v;
        v.view = static_cast<int>(i);
        const std::uint64_t buffer = unsignedField(*e, "buffer", true, where, file);
        if (buffer > INT_MAX) fail(file, where + ".buffer", "buffer " + std::to_string(buffer) + " is out of range");
        v.buffer = static_cast<int>(buffer);
        v.byteOffset = unsignedField(*e, "byteOffset", false, where, file);
        v.byteLength = unsignedField(*e, "byteLength", true, where, file);
        v.byteStride = unsignedField(*e, "byteStride", true, where, file);
        v.count = unsignedField(*e, "count", true, where, file);
        const auto mode = e->find("mode");
        if (mode == e->end()) fail(file, where + ".mode", "missing (expected ATTRIBUTES, TRIANGLES or INDICES)");
        v.mode = parseMode(stringField(*e, "mode", "", where, file), where + ".mode", file);
        v.filter = parseFilter(stringField(*e, "filter", "NONE", where, file), where + ".filter", file);
        checkLayout(v, where, file);
        views.push_back(v);
    }
    return views;
}

std::vector<int> standInFallbackBuffers(nlohmann::json& doc, bool glb) {
    std::vector<int> fallbacks;
    const auto list = doc.find("buffers");
    if (list == doc.end() || !list->is_array()) return fallbacks;
    for (std::size_t i = 0; i < list->size() && i <= INT_MAX; ++i) {
        Json& b = (*list)[i];
        if (!b.is_object()) continue;
        bool fallback = !b.contains("uri") && !(glb && i == 0);
        if (b.contains("extensions") && b["extensions"].is_object() && b["extensions"].contains(kMeshoptExt)) {
            const Json& e = b["extensions"][kMeshoptExt];
            fallback = fallback || (e.is_object() && e.contains("fallback") && e["fallback"] == true);
        }
        if (!fallback) continue;
        b["uri"] = "data:application/octet-stream;base64,AA==";
        b["byteLength"] = 1;
        fallbacks.push_back(static_cast<int>(i));
    }
    return fallbacks;
}

void decodeMeshoptViews(tinygltf::Model& model, const MeshoptLayout& layout, const std::string& file) {
    const std::vector<int>& fallbacks = layout.fallbackBuffers;
    auto isFallback = [&](int b) { return std::binary_search(fallbacks.begin(), fallbacks.end(), b); };
    std::set<int> compressed;
    for (const MeshoptView& v : layout.views) compressed.insert(v.view);
    for (std::size_t i = 0; i < model.bufferViews.size(); ++i)
        if (isFallback(model.bufferViews[i].buffer) && !compressed.count(static_cast<int>(i)))
            fail(file, "bufferViews[" + std::to_string(i) + "]",
                 "buffer " + std::to_string(model.bufferViews[i].buffer) +
                     " is a fallback buffer without data (expected EXT_meshopt_compression on every view of it)");
    // Every check (and the total) before the first allocation.
    std::uint64_t total = 0, sources = 0;
    std::set<int> sourceBuffers;
    std::vector<const MeshoptView*> toDecode;
    for (const MeshoptView& v : layout.views) {
        const std::uint64_t decoded = checkAgainstModel(model, v, fallbacks, file);
        if (!isFallback(model.bufferViews[v.view].buffer)) continue;  // uncompressed data is there
        toDecode.push_back(&v);
        total += decoded;
        if (sourceBuffers.insert(v.buffer).second) sources += model.buffers[v.buffer].data.size();
    }
    if (sources > 0 && total / kMaxMeshoptExpansion > sources)
        fail(file, std::string("bufferViews (") + kMeshoptExt + ")",
             "the compressed views decode to " + std::to_string(total) + " bytes from " + std::to_string(sources) +
                 " bytes of buffers (expected at most " + std::to_string(kMaxMeshoptExpansion) + " per byte)");
    for (const MeshoptView* v : toDecode) {
        tinygltf::Buffer decoded;
        decoded.name = "decoded bufferViews[" + std::to_string(v->view) + "]";
        decoded.data.resize(static_cast<std::size_t>(v->byteStride * v->count));
        decodeOne(*v, model.buffers[v->buffer].data.data() + v->byteOffset, decoded.data.data(), file);
        model.buffers.push_back(std::move(decoded));
        model.bufferViews[v->view].buffer = static_cast<int>(model.buffers.size()) - 1;
        model.bufferViews[v->view].byteOffset = 0;
    }
}

}  // namespace cavewall::scenes
