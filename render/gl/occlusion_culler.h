#pragma once
// Occlusion culling on the GPU, in two phases per view, with what each view saw in its last
// frame (the scheme of GPU-driven renderers: Hill and Collin 2011's hierarchical-Z culling,
// split in two so that nothing visible is ever left out):
//   1. `selectSeen` turns on the draws of the objects this view's slot saw last frame (opaque
//      draws only) and the caller draws them.
//   2. `buildPyramid` reduces the depth drawn so far to a hierarchical-Z pyramid (level 0 the
//      farthest depth of each 4 x 4 pixels, each level above the farthest of the 2 x 2 texels
//      below it; reversed-Z, so the minimum), and `selectRevealed`
//      tests every draw's box against it: a draw whose box is nearer than the farthest depth
//      under it somewhere is visible. The caller draws the visible draws phase 1 left out (and
//      the visible blended draws), and the slot remembers what is visible for its next frame.
// Every draw phase 1 leaves out is tested against depth that only drawn surfaces wrote, so the
// image is the one drawing everything gives: culling saves work, it never changes a pixel
// (beyond depth ties between coincident surfaces, which drawing order decides either way).
//
// A draw's box: the scene renderer's stored positions are normalised within the mesh's box, so
// in stored coordinates every mesh (at every level of detail) lies in the unit cube, and its
// record's model-view rows (shaders::DrawRecord) place that cube in the view.
//
// Everything runs in compute shaders on buffers the renderer already has (its draw records and
// indirect commands): no wait; the counts of what was drawn stay on the GPU until a caller asks
// (readCounts, which waits). What culling saves is measured per slot and read back only once
// the GPU has finished that frame (worthCulling): a view where culling hides little is drawn
// whole for a while instead of paying for a pyramid that saves nothing.

#include "display/gl/gl_object.h"
#include "render/occlusion_settings.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <map>
#include <utility>

namespace cavewall::render::gl {

// Draws and triangles drawn through the culler since the last readCounts, and what the
// commands asked for before culling.
struct OcclusionCounts {
    std::uint64_t drawsSubmitted = 0, drawsDrawn = 0;
    std::uint64_t trianglesSubmitted = 0, trianglesDrawn = 0;
};

// One view's draw: its buffers on the GPU. `commands` (read) holds every draw with one
// instance; phase 1 and 2 write their own copies. `objects` holds each record's object index.
struct CullBuffers {
    GLuint records = 0, commands = 0, objects = 0, phase1 = 0, phase2 = 0;
    std::uint32_t count = 0;         // commands
    std::uint32_t firstBlended = 0;  // records from this index on are blended (drawn in phase 2)
};

class OcclusionCuller {
public:
    // Needs a current GL 4.5 context. `objectCount`: the scene's objects (each slot's memory).
    explicit OcclusionCuller(std::size_t objectCount);
    ~OcclusionCuller();
    OcclusionCuller(const OcclusionCuller&) = delete;
    OcclusionCuller& operator=(const OcclusionCuller&) = delete;

    // Whether `slot` is culled this frame (then selectSeen and selectRevealed follow). A slot
    // whose last measured culled frames left out less than `minSavedShare` of the triangles
    // they submitted is drawn whole for this frame and the next
    // render::kOcclusionPausedFrames - 1, then measured again. Measured are the frames from
    // the third culled in a row on; a measure in which phase 2 revealed more than phase 1
    // redrew (what the view saw last frame was stale: the eye jumped) decides nothing. The
    // measure is read once a fence says the GPU has finished those frames (polled, never
    // waited for); until then the slot is culled. minSavedShare 0: always culled, nothing
    // measured.
    bool worthCulling(std::uint64_t slot, double minSavedShare);

    // Phase 1: writes buffers.phase1 with the opaque draws `slot` saw last frame turned on.
    // A slot is a view of a caller's frame loop (e.g. screen and eye); a new slot saw nothing.
    void selectSeen(std::uint64_t slot, const CullBuffers& buffers);
    // Reduces `depthTexture`'s `viewport` (pixels, origin lower-left) to the pyramid.
    void buildPyramid(GLuint depthTexture, glm::ivec4 viewport);
    // Phase 2: writes buffers.phase2 with the draws visible against the pyramid that phase 1
    // did not draw; remembers the visible opaque draws' objects in `slot`. `projection` is the
    // view's clip-from-view matrix (the records' model-view rows are eye-relative).
    void selectRevealed(std::uint64_t slot, const CullBuffers& buffers, const glm::mat4& projection);
    // Waits for the GPU and returns the counts since the last call (then zero).
    OcclusionCounts readCounts();

private:
    // One view's memory between frames.
    struct Slot {
        display::gl::GlObject seen;  // uint per object; then triangles submitted, drawn in phase 1, 2
        GLsync fence = nullptr;      // after the last culled frame's phase 2, until read
        int paused = 0;              // frames still to draw whole
        // Frames culled in a row before this one. A frame is measured from the third on: the
        // first tests against the empty depth of a view that saw nothing (or long ago), so it
        // finds everything visible and the second draws all that in phase 1.
        int streak = 0;
        bool measured = false;  // this frame counts in the measure (set by worthCulling)
    };
    Slot& slotOf(std::uint64_t slot);
    void allocatePyramid(glm::ivec2 size);
    static void dispatch2d(glm::ivec2 size);
    void bindCommon(const CullBuffers& buffers, GLuint visible);

    std::size_t _objects;
    display::gl::GlObject _selectProgram, _reduceFirstProgram, _reduceProgram, _testProgram;
    GLint _firstOffset = -1, _firstSourceSize = -1, _firstTargetSize = -1;
    GLint _selectCount = -1, _selectFirstBlended = -1, _selectMeasure = -1, _testMeasure = -1;
    GLint _reduceSourceSize = -1, _reduceTargetSize = -1, _reduceLevel = -1;
    GLint _testCount = -1, _testFirstBlended = -1, _testProjection = -1, _testViewport = -1, _testLevels = -1;
    display::gl::GlObject _sampler;  // nearest texel, for the depth textures and the pyramid
    display::gl::GlObject _pyramid;  // R32F, mip levels
    glm::ivec2 _pyramidSize{0, 0};   // level 0's allocated size
    int _pyramidLevels = 0;          // allocated
    int _levels = 0;                 // used by the last buildPyramid
    glm::ivec2 _viewportSize{0, 0};  // of the last buildPyramid
    display::gl::GlObject _counts;   // uint[4]: draws submitted, drawn, triangles submitted, drawn
    std::map<std::uint64_t, Slot> _slots;
};

}  // namespace cavewall::render::gl
