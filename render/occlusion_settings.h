#pragma once
// When a view's draws are culled against the depth drawn so far (occlusion culling on the GPU,
// render/gl/occlusion_culler.h): plain data shared by the scene renderer, the commands that set
// it and the reports that state it.

#include <cstddef>
#include <string>

namespace cavewall::render {

// The frames a view is drawn whole after culled frames that saved too little (minSavedShare).
inline constexpr int kOcclusionPausedFrames = 16;

// Each culled view first draws what it saw last frame, then only what that depth does not
// hide; the image is the same as drawing the whole list. Culling has a cost of its own per view
// (a depth pyramid, a second phase) and it culls whole draws, so a list of few triangles or of
// a few large draws has little to leave out: such a list is drawn whole. 100,000 triangles in
// 500 draws is where it paid on llvmpipe at 1024 x 1024 per view: the clinic's 2,700 draws a
// view gained, the generated plant's 91 lost (docs/benchmarking.md, "Occlusion culling"). A
// GPU's break-even differs. 0 in either threshold: no limit.
struct OcclusionSettings {
    bool on = true;
    std::size_t minTriangles = 100000;  // the least triangles a culled view's list submits
    std::size_t minDraws = 500;         // the least draws in it
    // A view whose culled frames left out less than this share of the triangles they submitted
    // is drawn whole for the next kOcclusionPausedFrames frames, then measured again (render/gl/occlusion_culler.h,
    // worthCulling): where the depth hides little, the pyramid costs more than it saves. 0:
    // never paused.
    double minSavedShare = 0.1;

    // Whether a list of `triangles` in `draws` draws is culled.
    bool culls(std::size_t triangles, std::size_t draws) const {
        return on && triangles >= minTriangles && draws >= minDraws;
    }
};

// "on, in views whose list submits at least N triangles in at least D draws, paused for 16
// frames in a view where it saved under S % of them" or "off".
std::string describe(const OcclusionSettings& settings);

}  // namespace cavewall::render
