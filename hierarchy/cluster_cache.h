#pragma once
// The files of a cluster's impostors in the cache, GL-free (hierarchy/gl/cluster_impostors.h
// makes, reads and draws them): <cache>/clusters/<16 hex digits>/ holds one MIP file per face
// and viewing region (f<face>r<region>.tx, walls/texture_mips.h's tiled TIFF) and cluster.json:
//   {"version": 2,
//    "files": {"f0r0.tx": {"bytes": N, "hash": "<16 hex digits>"}, ... every face and region},
//    "averages": [[r, g, b, coverage] x 6 faces],   linear colour and coverage, each in [0, 1]
//    "textured": [6 accuracies], "average": [6 accuracies]}   each in [0, 1]
// A folder whose cluster.json is of another version is stale (made again).
// Everything read is checked before it is used: a reader never trusts a cache file.

#include "hierarchy/cluster_frame.h"
#include "hierarchy/cluster_impostor.h"
#include "scenes/scene.h"

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace cavewall::hierarchy {

// The cluster.json version written.
inline constexpr int kClusterCacheVersion = 2;

// "f<face>r<region>.tx".
std::string impostorFileName(int face, int region);

struct ListedFile {
    std::uint64_t bytes = 0;
    std::uint64_t hash = 0;  // walls/content_hash.h's of the file's bytes
    bool operator==(const ListedFile&) const = default;
};

struct ClusterRecord {
    int version = kClusterCacheVersion;  // another: stale, and nothing else is read
    std::array<FaceAverage, kBoxFaces> faces{};
    ClusterAccuracy accuracy;
    std::map<std::string, ListedFile> files;  // by impostorFileName, every face and region
    bool operator==(const ClusterRecord&) const = default;
};

// Parses cluster.json text. Throws cavewall::Error naming `source` and the field: not JSON,
// unknown keys, a missing file, a number out of range.
ClusterRecord parseClusterRecord(std::string_view text, const std::string& source);
std::string clusterRecordJson(const ClusterRecord& record);

// Why `levels`, read from an impostor file, are not the MIP chain of a `size` texture (each
// level max(1, floor(previous / 2)) per side down to 1 x 1, RGBA8), else empty.
std::string impostorLevelsProblem(const std::vector<scenes::Image>& levels, glm::ivec2 size);

}  // namespace cavewall::hierarchy
