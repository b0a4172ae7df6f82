// The OBJ writer: what osgconv reads must be the same geometry cavewall draws.
#include "scenes/obj_writer.h"
#include "scenes/primitives.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <sstream>
#include <string>
#include <vector>

namespace cavewall::scenes {
namespace {

struct ObjCounts {
    std::vector<glm::vec3> positions, normals;
    std::vector<std::string> faces;
};

ObjCounts parse(const std::string& text) {
    ObjCounts c;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string tag;
        words >> tag;
        glm::vec3 v;
        if (tag == "v" && words >> v.x >> v.y >> v.z) c.positions.push_back(v);
        if (tag == "vn" && words >> v.x >> v.y >> v.z) c.normals.push_back(v);
        if (tag == "f") c.faces.push_back(line);
    }
    return c;
}

TEST(ObjWriter, BoxesShareCornersAndNormalsInWorldCoordinates) {
    Scene s;
    s.name = "two boxes";
    s.meshes.push_back(makeBox({1, 2, 4}, glm::vec4(1.0f)));
    addObject(s, 0, glm::translate(glm::dmat4(1.0), glm::dvec3(10, 0, 0)), "a");
    addObject(s, 0, glm::translate(glm::dmat4(1.0), glm::dvec3(-10, 0, 0)), "b");
    const ObjCounts c = parse(objText(s));
    // A box has 24 vertices but 8 distinct corners and 6 distinct normals; the second box adds
    // 8 corners and no normal.
    EXPECT_EQ(c.positions.size(), 16u);
    EXPECT_EQ(c.normals.size(), 6u);
    EXPECT_EQ(c.faces.size(), 24u);
    // World coordinates: the first box's corners are at x = 10 +- 0.5.
    EXPECT_FLOAT_EQ(std::abs(c.positions[0].x - 10.0f), 0.5f);
    EXPECT_FLOAT_EQ(std::abs(c.positions[0].z), 2.0f);
    EXPECT_EQ(c.faces[0].substr(0, 2), "f ");
    EXPECT_NE(c.faces[0].find("//"), std::string::npos);
}

TEST(ObjWriter, MirroredObjectsKeepCounterClockwiseFrontFaces) {
    Scene s;
    s.meshes.push_back(makeBox({1, 1, 1}, glm::vec4(1.0f)));
    addObject(s, 0, glm::scale(glm::dmat4(1.0), glm::dvec3(-1, 1, 1)), "mirrored");
    const ObjCounts c = parse(objText(s));
    for (const std::string& f : c.faces) {
        int p[3], n[3];
        ASSERT_EQ(std::sscanf(f.c_str(), "f %d//%d %d//%d %d//%d", &p[0], &n[0], &p[1], &n[1], &p[2], &n[2]), 6);
        const glm::vec3 a = c.positions[p[0] - 1], b = c.positions[p[1] - 1], d = c.positions[p[2] - 1];
        // The winding's normal points the same way as the written (mirrored) normal.
        EXPECT_GT(glm::dot(glm::cross(b - a, d - a), c.normals[n[0] - 1]), 0.0f) << f;
    }
}

}  // namespace
}  // namespace cavewall::scenes
