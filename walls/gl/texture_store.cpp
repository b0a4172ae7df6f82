#include "walls/gl/texture_store.h"

#include "walls/gl/depth_wall_pass.h"
#include "walls/gl/wall_quad.h"

#include <algorithm>

namespace cavewall::walls::gl {

TextureStore::TextureStore(walls::TexturePager& pager, std::size_t uploadBytesPerFrame)
    : _pager(pager), _uploadBytes(std::max<std::size_t>(uploadBytesPerFrame, 1)), _pacer(_uploadBytes),
      _sampler(wallSampler()) {}

display::gl::GlObject wallSampler() {
    display::gl::GlObject s = display::gl::createSampler();
    glSamplerParameteri(s.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
    glSamplerParameteri(s.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return s;
}

std::size_t TextureStore::update() {
    const std::size_t inFlight = _inFlight ? _inFlight->cursor->remainingBytes() : 0;
    const std::size_t allowed = _pacer.allowance(_pager.readyBytes() + inFlight);
    std::size_t uploaded = 0;
    // Wanted now: whole and at once, a prefetch in flight included.
    if (_inFlight && _pager.wantedNow(_inFlight->decoded.id)) uploaded += finishInFlight();
    while (uploaded < _uploadBytes)
        if (std::optional<walls::DecodedTexture> d = _pager.takeNext(true))
            uploaded += finishWhole(std::move(*d));
        else
            break;
    // Prefetches: bands within what the pacer allows, what the frame wants now counted in.
    while (uploaded < allowed) {
        if (!_inFlight) {
            std::optional<walls::DecodedTexture> d = _pager.takeNext(false);
            if (!d) break;
            display::gl::GlObject texture = createWallTexture(d->levels);
            _inFlight.emplace(InFlight{std::move(*d), std::move(texture), nullptr});
            _inFlight->cursor = std::make_unique<walls::UploadCursor>(_inFlight->decoded.levels);
        }
        uploaded += advance(allowed - uploaded);
    }
    _pacer.uploaded(uploaded);
    for (int id : _pager.takeEvictions()) _textures.erase(id), _depthTextures.erase(id), _contents.erase(id);
    return uploaded;
}

std::size_t TextureStore::updateAll() {
    std::size_t uploaded = _inFlight ? finishInFlight() : 0;
    while (std::optional<walls::DecodedTexture> d = _pager.takeNext(false)) uploaded += finishWhole(std::move(*d));
    for (int id : _pager.takeEvictions()) _textures.erase(id), _depthTextures.erase(id), _contents.erase(id);
    return uploaded;
}

std::size_t TextureStore::finishWhole(walls::DecodedTexture d) {
    return d.levels.bytes() + makeResident(d, uploadWallTexture(d.levels));
}

// Colour uploaded: the depth goes up at once, then both count as resident. Returns the depth's bytes.
std::size_t TextureStore::makeResident(walls::DecodedTexture& d, display::gl::GlObject colour) {
    std::size_t depthBytes = 0;
    if (d.depth) {
        _depthTextures[d.id] = {uploadDepthTexture(*d.depth),
                                d.depth->samplingPoint,
                                d.depth->range,
                                d.depth->content,
                                {d.depth->depth.width, d.depth->depth.height}};
        depthBytes = d.depth->gpuBytes();
    }
    _textures[d.id] = std::move(colour);
    _contents[d.id] = d.content;
    _pager.markResident(d.id, d.bytes);
    return depthBytes;
}

std::size_t TextureStore::advance(std::size_t maxBytes) {
    // One band (within one level); the callers loop while bytes remain.
    InFlight& f = *_inFlight;
    const walls::UploadPiece piece = f.cursor->next(maxBytes);
    uploadWallTextureBand(f.texture.id(), f.decoded.levels, piece);
    std::size_t bytes = piece.bytes;
    if (f.cursor->done()) {
        bytes += makeResident(f.decoded, std::move(f.texture));
        _inFlight.reset();
    }
    return bytes;
}

std::size_t TextureStore::finishInFlight() {
    std::size_t uploaded = 0;
    while (_inFlight) uploaded += advance(_inFlight->cursor->remainingBytes());
    return uploaded;
}

GLuint TextureStore::texture(int id) const {
    auto it = _textures.find(id);
    return it == _textures.end() ? 0 : it->second.id();
}

walls::TextureRect TextureStore::content(int id) const {
    auto it = _contents.find(id);
    return it == _contents.end() ? walls::TextureRect{} : it->second;
}

std::optional<DepthWallLayer> TextureStore::depthLayer(int id) const {
    const auto depth = _depthTextures.find(id);
    const GLuint colour = texture(id);
    if (depth == _depthTextures.end() || colour == 0) return std::nullopt;
    const ResidentDepth& d = depth->second;
    return DepthWallLayer{colour, d.texture.depth.id(), d.samplingPoint, d.range,
                          0.0f,   d.texture.skip.id(),  d.content,       d.texels};
}

}  // namespace cavewall::walls::gl
