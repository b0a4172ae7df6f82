#pragma once
// GPU residency of baked wall textures: the GL side of walls/texture_pager.h.
//
// Each frame the runtime tells the pager what it wants, then calls update(): textures wanted now
// are uploaded at once and whole (up to `uploadBytesPerFrame`, at least one: a large texture
// cannot starve); prefetches go up in bands (walls/upload_cursor.h) at the byte rate
// walls/upload_pacer.h allows, one texture at a time, drawn once its last band is up (a prefetch
// the frame comes to want now is finished at once). Then it deletes the textures the pager evicted.
// updateAll() uploads everything ready (warm-up, synchronous paging). Textures are
// GL_SRGB8_ALPHA8, or the sRGB S3TC formats of ".bct" files
// (walls/texture_blocks.h, uploaded compressed), with every MIP level the file had (premultiplied
// alpha, as baked), sampled bilinearly in the nearest MIP level and clamped to the edge. A depth wall's texture comes
// with its depth texture (gl::uploadDepthTexture), uploaded with the colour's last piece and
// deleted with it, and with what the march needs to read it (depthLayer).
// Needs the rendering context current for every call and for destruction.

#include "display/gl/gl_object.h"
#include "walls/gl/depth_wall_pass.h"
#include "walls/texture_pager.h"
#include "walls/upload_cursor.h"
#include "walls/upload_pacer.h"

#include <cstddef>
#include <map>
#include <memory>
#include <optional>

namespace cavewall::walls::gl {

// The walls' sampler: bilinear within the nearest MIP level, clamped to the edge.
display::gl::GlObject wallSampler();

class TextureStore {
public:
    // Keeps a reference to `pager`, which must outlive the store.
    TextureStore(walls::TexturePager& pager, std::size_t uploadBytesPerFrame);

    // Uploads what is ready (within the per-frame byte budget) and deletes evicted textures.
    // Returns the bytes uploaded.
    std::size_t update();
    std::size_t updateAll();

    // The GL texture of texture `id`, or 0 when it is not resident.
    GLuint texture(int id) const;
    bool resident(int id) const { return texture(id) != 0; }
    // Texture `id` as a depth wall's layer (depth walls; weight 0): its colour, depth and skip
    // blocks (DepthTexture::skip; 0 when the image is too small for any), with the sampling point
    // and baked range that came with its depths. Nothing when it is not resident or has no depth.
    std::optional<DepthWallLayer> depthLayer(int id) const;
    GLuint sampler() const { return _sampler.id(); }
    // Where resident texture `id` has content (walls::DecodedTexture::content); the whole texture
    // when it is not resident.
    walls::TextureRect content(int id) const;

private:
    // A prefetch partly uploaded: its levels, texture and where its next band starts.
    struct InFlight {
        walls::DecodedTexture decoded;
        display::gl::GlObject texture;
        std::unique_ptr<walls::UploadCursor> cursor;  // points into decoded.levels
    };
    std::size_t finishWhole(walls::DecodedTexture d);  // uploads all of `d` and makes it resident
    std::size_t advance(std::size_t maxBytes);         // uploads the in-flight prefetch's next band
    std::size_t finishInFlight();
    std::size_t makeResident(walls::DecodedTexture& d, display::gl::GlObject colour);  // the depth uploaded here

    walls::TexturePager& _pager;
    std::size_t _uploadBytes;
    walls::UploadPacer _pacer;
    std::optional<InFlight> _inFlight;
    std::map<int, display::gl::GlObject> _textures;
    std::map<int, walls::TextureRect> _contents;
    // A resident texture's depths, and the sampling point and range they were baked from.
    struct ResidentDepth {
        DepthTexture texture;
        glm::dvec3 samplingPoint;
        glm::dvec2 range;
        walls::TextureRect content;
        glm::ivec2 texels{1, 1};
    };
    std::map<int, ResidentDepth> _depthTextures;
    display::gl::GlObject _sampler;
};

}  // namespace cavewall::walls::gl
