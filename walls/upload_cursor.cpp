#include "walls/upload_cursor.h"

#include <algorithm>
#include <cassert>

namespace cavewall::walls {

UploadCursor::UploadCursor(const TextureLevels& levels) : _levels(levels), _remaining(levels.bytes()) {
    while (!done() && levelHeight(_level) <= 0) ++_level;
}

int UploadCursor::levelWidth(std::size_t level) const {
    return _levels.format == TextureFormat::Rgba8 ? _levels.rgba[level].width : _levels.blocks[level].width;
}

int UploadCursor::levelHeight(std::size_t level) const {
    return _levels.format == TextureFormat::Rgba8 ? _levels.rgba[level].height : _levels.blocks[level].height;
}

std::size_t UploadCursor::rowUnitBytes(std::size_t level) const {
    const std::size_t width = static_cast<std::size_t>(std::max(levelWidth(level), 0));
    if (_levels.format == TextureFormat::Rgba8) return width * 4;
    return (width + 3) / 4 * static_cast<std::size_t>(blockBytes(_levels.format));
}

UploadPiece UploadCursor::next(std::size_t maxBytes) {
    assert(!done());
    const int rowsPerUnit = _levels.format == TextureFormat::Rgba8 ? 1 : 4;
    const int height = levelHeight(_level);
    const std::size_t unitBytes = std::max<std::size_t>(rowUnitBytes(_level), 1);
    const int unitsLeft = (height - _y + rowsPerUnit - 1) / rowsPerUnit;
    const int units =
        static_cast<int>(std::clamp<std::size_t>(maxBytes / unitBytes, 1, static_cast<std::size_t>(unitsLeft)));
    UploadPiece p;
    p.level = static_cast<int>(_level);
    p.y = _y;
    p.rows = std::min(units * rowsPerUnit, height - _y);
    p.offset = static_cast<std::size_t>(_y / rowsPerUnit) * unitBytes;
    p.bytes = static_cast<std::size_t>(units) * unitBytes;
    _y += p.rows;
    _remaining -= std::min(_remaining, p.bytes);
    if (_y >= height) {
        ++_level;
        _y = 0;
        // An empty level (0 rows) has nothing to upload: skip it.
        while (!done() && levelHeight(_level) <= 0) ++_level;
    }
    return p;
}

}  // namespace cavewall::walls
