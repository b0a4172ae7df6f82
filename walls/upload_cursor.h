#pragma once
// Cutting one texture's upload into pieces, so a frame can upload part of a texture: the
// uploader (walls/gl/texture_store.h) spends the pacer's byte allowance (walls/upload_pacer.h)
// exactly instead of in whole textures (a 512^2 BC1 chain is 175 kB, a whole frame's allowance
// on a slow walk is a few kB), and the texture is drawn once its last piece is up.
//
// A piece is a band of rows of one MIP level, largest level first. Rows go in the units the GPU
// takes them: one texel row for RGBA8, one row of 4 x 4 blocks for compressed levels (a band
// starts on a multiple of 4 texel rows and is a multiple of 4 rows high, or ends at the level's
// edge), so glTextureSubImage2D / glCompressedTextureSubImage2D take the band's bytes as they are
// stored: contiguous, from `offset`.
//
// Pure and deterministic; GL-free.

#include "walls/texture_blocks.h"

#include <cstddef>

namespace cavewall::walls {

struct UploadPiece {
    int level = 0;
    int y = 0, rows = 0;                // texel rows [y, y + rows) of the level
    std::size_t offset = 0, bytes = 0;  // of the level's stored bytes
};

class UploadCursor {
public:
    // `levels` must outlive the cursor and stay unchanged.
    explicit UploadCursor(const TextureLevels& levels);

    // The next band: as many whole row units of the current level as fit in `maxBytes`, at
    // least one (so an upload always progresses). Never crosses into the next level. Only when
    // done() is false.
    UploadPiece next(std::size_t maxBytes);
    bool done() const { return _level >= _levels.count(); }
    std::size_t remainingBytes() const { return _remaining; }

private:
    int levelWidth(std::size_t level) const;
    int levelHeight(std::size_t level) const;
    std::size_t rowUnitBytes(std::size_t level) const;  // bytes of one row unit

    const TextureLevels& _levels;
    std::size_t _level = 0;
    int _y = 0;  // next texel row of _level
    std::size_t _remaining = 0;
};

}  // namespace cavewall::walls
