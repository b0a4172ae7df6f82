#include "scenes/obj_writer.h"

#include "scenes/file_write.h"

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <unordered_map>
#include <vector>

namespace cavewall::scenes {
namespace {

// Indexes 3-vectors by their exact bits (OBJ indices are 1-based) and appends each new one as
// an OBJ line with `prefix`.
class VectorIndex {
public:
    explicit VectorIndex(const char* prefix) : _prefix(prefix) {}

    std::size_t add(glm::vec3 v, std::string& out) {
        std::array<std::uint32_t, 3> bits;
        std::memcpy(bits.data(), &v, sizeof(bits));
        const std::uint64_t key = hash(bits);
        auto [it, inserted] = _index.try_emplace(key, _bits.size() + 1);
        // Hash collisions between different vectors are resolved by writing the vector again.
        if (!inserted && _bits[it->second - 1] != bits) return append(bits, v, out);
        if (inserted) append(bits, v, out);
        return it->second;
    }

private:
    static std::uint64_t hash(const std::array<std::uint32_t, 3>& b) {
        std::uint64_t h = 1469598103934665603ull;
        for (std::uint32_t w : b) h = (h ^ w) * 1099511628211ull;
        return h;
    }
    std::size_t append(const std::array<std::uint32_t, 3>& bits, glm::vec3 v, std::string& out) {
        char line[96];
        // %.9g round-trips a float exactly; printf in the "C" locale never uses a decimal comma.
        const int n = std::snprintf(line, sizeof(line), "%s %.9g %.9g %.9g\n", _prefix, v.x, v.y, v.z);
        out.append(line, static_cast<std::size_t>(n));
        _bits.push_back(bits);
        return _bits.size();
    }

    const char* _prefix;
    std::unordered_map<std::uint64_t, std::size_t> _index;
    std::vector<std::array<std::uint32_t, 3>> _bits;
};

}  // namespace

std::string objText(const Scene& scene) {
    std::string vertices, normals, faces;
    VectorIndex positions("v"), normalIndex("vn");
    vertices += "# " + scene.name + ": written by cavewall (metres, +Y up)\n";
    for (const Object& o : scene.objects) {
        const Mesh& m = scene.meshes[o.mesh];
        const glm::dmat3 normalFromModel = glm::transpose(glm::inverse(glm::dmat3(o.worldFromModel)));
        std::vector<std::size_t> p(m.positions.size()), n(m.normals.size());
        for (std::size_t i = 0; i < p.size(); ++i)
            p[i] = positions.add(glm::vec3(o.worldFromModel * glm::dvec4(m.positions[i], 1.0)), vertices);
        for (std::size_t i = 0; i < n.size(); ++i)
            n[i] = normalIndex.add(glm::vec3(glm::normalize(normalFromModel * glm::dvec3(m.normals[i]))), normals);
        faces += "g " + o.name + "\n";
        char line[96];
        for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
            std::array<std::uint32_t, 3> k{m.indices[t], m.indices[t + 1], m.indices[t + 2]};
            if (o.flipWinding) std::swap(k[1], k[2]);
            int len = 0;
            if (n.empty())
                len = std::snprintf(line, sizeof(line), "f %zu %zu %zu\n", p[k[0]], p[k[1]], p[k[2]]);
            else
                len = std::snprintf(line, sizeof(line), "f %zu//%zu %zu//%zu %zu//%zu\n", p[k[0]], n[k[0]], p[k[1]],
                                    n[k[1]], p[k[2]], n[k[2]]);
            faces.append(line, static_cast<std::size_t>(len));
        }
    }
    return vertices + normals + faces;
}

void writeObj(const Scene& scene, const std::filesystem::path& file) { writeBytesAtomically(file, objText(scene)); }

}  // namespace cavewall::scenes
