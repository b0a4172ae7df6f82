#pragma once
// GPU residency of baked wall textures: the GL side of walls/texture_pager.h.
//
// Each frame the runtime tells the pager what it wants, then calls update(): it uploads the
// decoded textures the pager has ready (those wanted now at once, prefetches paced by
// walls/upload_pacer.h; at most `uploadBytesPerFrame` per frame, at least one texture when any
// is ready, so a large texture cannot starve) and deletes the textures the pager evicted.
// updateAll() uploads everything ready (warm-up, synchronous paging). Textures are
// GL_SRGB8_ALPHA8, or the sRGB S3TC formats of ".bct" files
// (walls/texture_blocks.h, uploaded compressed), with every MIP level the file had (premultiplied
// alpha, as baked), sampled trilinearly and clamped to the edge.
// Needs the rendering context current for every call and for destruction.

#include "display/gl/gl_object.h"
#include "walls/texture_pager.h"
#include "walls/upload_pacer.h"

#include <cstddef>
#include <map>

namespace cavewall::gl {

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
    GLuint sampler() const { return _sampler.id(); }

private:
    std::size_t upload(std::size_t maxBytes, std::size_t maxNowBytes = 0);  // one takeReady round, then evictions

    walls::TexturePager& _pager;
    std::size_t _uploadBytes;
    walls::UploadPacer _pacer;
    std::map<int, GlObject> _textures;
    GlObject _sampler;
};

}  // namespace cavewall::gl
