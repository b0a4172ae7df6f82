#include "walls/gl/texture_store.h"

#include "walls/gl/wall_quad.h"

#include <algorithm>

namespace cavewall::gl {

TextureStore::TextureStore(walls::TexturePager& pager, std::size_t uploadBytesPerFrame)
    : _pager(pager), _uploadBytes(std::max<std::size_t>(uploadBytesPerFrame, 1)), _pacer(_uploadBytes),
      _sampler(createSampler()) {
    glSamplerParameteri(_sampler.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
    glSamplerParameteri(_sampler.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(_sampler.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(_sampler.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

std::size_t TextureStore::update() {
    const std::size_t uploaded = upload(_pacer.allowance(_pager.readyBytes()), _uploadBytes);
    _pacer.uploaded(uploaded);
    return uploaded;
}

std::size_t TextureStore::updateAll() {
    std::size_t uploaded = 0;
    do uploaded += upload(_uploadBytes);
    while (_pager.readyBytes() > 0);
    return uploaded;
}

std::size_t TextureStore::upload(std::size_t maxBytes, std::size_t maxNowBytes) {
    std::size_t uploaded = 0;
    for (const walls::DecodedTexture& d : _pager.takeReady(maxBytes, maxNowBytes)) {
        if (d.levels.count() == 0 || d.levels.width() <= 0 || d.levels.height() <= 0) continue;
        _textures[d.id] = uploadWallTexture(d.levels);
        _pager.markResident(d.id, d.bytes);
        uploaded += d.bytes;
    }
    for (int id : _pager.takeEvictions()) _textures.erase(id);
    return uploaded;
}

GLuint TextureStore::texture(int id) const {
    auto it = _textures.find(id);
    return it == _textures.end() ? 0 : it->second.id();
}

}  // namespace cavewall::gl
