#pragma once
// glTF images, textures and materials to scenes::Image/Material (internal to the glTF loader).

#include "scenes/gltf_accessors.h"
#include "scenes/scene.h"

#include <string>
#include <vector>

namespace cavewall::scenes {

// Throws when the file requires an extension we cannot ignore safely, naming it. Supported or
// harmless: KHR_texture_transform, KHR_materials_*, KHR_mesh_quantization,
// EXT_meshopt_compression, KHR_draco_mesh_compression. KHR_texture_basisu (KTX2 images) is not:
// a file that only uses it loads its PNG/JPEG fallback images; a texture without one throws.
void checkRequiredExtensions(const GltfContext& ctx);

// The images the loader decoded (8-bit RGBA, by glTF image index, reduced: gltf_loader.cpp's
// ImageDecoder) into scene.images, named. An image that could not be decoded becomes an empty
// Image and a warning; textures using it are dropped with a warning.
void convertImages(const GltfContext& ctx, std::vector<Image> decoded, Scene& scene,
                   std::vector<std::string>& warnings);

// Materials in glTF order (same indices). Texture and image references are validated.
void convertMaterials(const GltfContext& ctx, Scene& scene, std::vector<std::string>& warnings);

// The 3x3 KHR_texture_transform matrix (T * R * S) for offset, rotation (radians) and scale.
glm::mat3 textureTransform(glm::vec2 offset, float rotation, glm::vec2 scale);

}  // namespace cavewall::scenes
