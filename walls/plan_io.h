#pragma once
// The plan as a JSON document (for tools outside cavewall that check the bound) and as a
// printed summary.
//
// JSON: {"alphaDeg": 10, "wallKind": "flat" | "depth" (optional when read: flat),
//        "walls": [{"id", "lowerLeft", "lowerRight", "upperLeft", "cells": [front, back],
//                   "depthBehind": metres or null when unknown,
//                   "depthNear": metres (optional when read: 0)}],
//        "zones": [{"id", "cell", "wall", "kind": "texture" | "blend" | "geometry",
//                   "floorPolygon": [[x, z], ...], "heightRange": [y0, y1],
//                   "samplingPoint": [x, y, z]            (texture zones)
//                   "samplingPoints": [[x, y, z], ...],   (blend zones: every texture mixed)
//                   "mixesGeometry": bool                 (blend zones: also fades to geometry)}],
//        "beyondZones": [{the keys of a zone, "eyeCell", "viaWall"}],
//        "textures": [{"id", "cell", "wall", "samplingPoint", "resolution": [x, y],
//                      "maxError": radians, the bound proven over the texture's valid region, for the
//                      plan's wall kind (Texture::maxError)}]  (optional when read)}
// Beyond zones (Plan::beyond, walls/plan.h) serve the far wall `wall` of the neighbour `cell`
// drawn as geometry, for eyes in the zone's floor polygon, which lies in cell `eyeCell` (in its
// geometry zone or texture->geometry blend strip of wall `viaWall`, a wall of eyeCell or, at the
// second level, the far wall of a first-level neighbour whose beyond zones draw `cell`'s
// neighbour as geometry; -1: anywhere in eyeCell, which sees the neighbour through an open
// boundary). The same bound holds for them: every eye
// of the zone, every texture listed. "beyondZones" is optional when read.
// Coordinates are world metres (config/conventions.h); floor polygons are (x, z).

#include "scenes/scene_description.h"
#include "walls/plan.h"

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>
#include <string_view>

namespace cavewall::walls {

nlohmann::json planToJson(const Plan& plan);

// Reads a plan document; textures are those listed, or without a "textures" list rebuilt from
// the distinct sampling points of each cell and wall (resolution and maxError then stay 0). Throws cavewall::Error with the
// JSON path on bad input.
Plan planFromJson(std::string_view text, const std::string& source);

struct PlanTotals {
    int textureZones = 0, blendZones = 0, geometryZones = 0;  // of the cells' own sides
    int beyondZones = 0, beyondTextures = 0;                  // of Plan::beyond
    int textures = 0;                                         // all, beyond ones included
    double texels = 0;                                        // base level texels over all textures
    double gpuBytes = 0;                                      // RGBA8 with a full MIP chain (4/3 of the base level)
    double diskBytes = 0;    // same, uncompressed: an upper bound for tiled MIP-mapped files
                             // (depth walls: both + 4 bytes of depth per base-level texel)
    double maxErrorDeg = 0;  // largest Texture::maxError, degrees
};
PlanTotals planTotals(const Plan& plan);

// The summary table of `cavewall plan`: one line per cell and wall, then totals and the texel
// density rule.
void printPlanSummary(std::ostream& out, const Plan& plan, const scenes::SceneDescription& description);

}  // namespace cavewall::walls
