#include "scenes/gltf_materials.h"

#include <cmath>

namespace cavewall::scenes {

void checkRequiredExtensions(const GltfContext& ctx) {
    const auto& required = ctx.model.extensionsRequired;
    for (std::size_t i = 0; i < required.size(); ++i) {
        const std::string& e = required[i];
        // These change only shading details, use attribute types the accessor reader handles, or
        // are decoded on loading (gltf_meshopt.h, gltf_draco.h).
        if (e == "KHR_texture_transform" || e.rfind("KHR_materials_", 0) == 0 || e == "KHR_mesh_quantization" ||
            e == "EXT_meshopt_compression" || e == "KHR_draco_mesh_compression")
            continue;
        const std::string hint = e == "KHR_texture_basisu" || e == "EXT_texture_webp" || e == "MSFT_texture_dds"
                                     ? "; textures must have a PNG or JPEG image"
                                     : "";
        ctx.fail("extensionsRequired[" + std::to_string(i) + "]",
                 "extension '" + e + "' is not supported" + hint +
                     " (supported: KHR_texture_transform, KHR_materials_*, KHR_mesh_quantization, "
                     "EXT_meshopt_compression, KHR_draco_mesh_compression)");
    }
}

void convertImages(const GltfContext& ctx, std::vector<Image> decoded, Scene& scene,
                   std::vector<std::string>& warnings) {
    for (std::size_t i = 0; i < ctx.model.images.size(); ++i) {
        const tinygltf::Image& src = ctx.model.images[i];
        Image img;
        if (i < decoded.size()) img = std::move(decoded[i]);
        img.name = !src.uri.empty() && src.uri.rfind("data:", 0) != 0 ? src.uri : "image " + std::to_string(i);
        if (img.rgba.empty())
            warnings.push_back("image " + std::to_string(i) + " ('" + img.name +
                               "') could not be decoded; "
                               "materials using it are drawn untextured");
        scene.images.push_back(std::move(img));
    }
}

glm::mat3 textureTransform(glm::vec2 offset, float rotation, glm::vec2 scale) {
    // KHR_texture_transform, written row-major in the spec:
    // T = [1 0 ox; 0 1 oy; 0 0 1], R = [cos sin 0; -sin cos 0; 0 0 1], S = diag(sx, sy, 1).
    const float c = std::cos(rotation), s = std::sin(rotation);
    const glm::mat3 t(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);  // columns
    const glm::mat3 r(c, -s, 0, s, c, 0, 0, 0, 1);
    const glm::mat3 sc(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
    return t * r * sc;
}

namespace {

double numberOr(const tinygltf::Value& obj, const char* key, int index, double fallback) {
    if (!obj.IsObject() || !obj.Has(key)) return fallback;
    const tinygltf::Value& v = obj.Get(key);
    const tinygltf::Value& n =
        index < 0 ? v : (v.IsArray() && v.ArrayLen() > static_cast<size_t>(index) ? v.Get(index) : tinygltf::Value());
    return n.IsNumber() && std::isfinite(n.GetNumberAsDouble()) ? n.GetNumberAsDouble() : fallback;
}

Wrap wrapOf(int mode) {
    if (mode == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) return Wrap::ClampToEdge;
    if (mode == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) return Wrap::MirroredRepeat;
    return Wrap::Repeat;
}

TextureRef convertTexture(const GltfContext& ctx, const Scene& scene, const tinygltf::TextureInfo& info,
                          const std::string& where, std::vector<std::string>& warnings) {
    TextureRef ref;
    const auto& textures = ctx.model.textures;
    if (info.index < 0 || static_cast<std::size_t>(info.index) >= textures.size())
        ctx.fail(where + ".index", "texture " + std::to_string(info.index) + " is out of range (expected < " +
                                       std::to_string(textures.size()) + " textures)");
    const tinygltf::Texture& tex = textures[info.index];
    const std::string tw = "textures[" + std::to_string(info.index) + "]";
    if (tex.source < 0 && !tex.extensions.empty())
        ctx.fail(tw, "has no PNG or JPEG source, only an image of extension '" + tex.extensions.begin()->first +
                         "', which is not supported (expected a 'source' image)");
    if (tex.source < 0 || static_cast<std::size_t>(tex.source) >= scene.images.size())
        ctx.fail(tw + ".source", "image " + std::to_string(tex.source) + " is out of range (expected < " +
                                     std::to_string(scene.images.size()) + " images)");
    if (tex.sampler >= 0) {
        if (static_cast<std::size_t>(tex.sampler) >= ctx.model.samplers.size())
            ctx.fail(tw + ".sampler", "sampler " + std::to_string(tex.sampler) + " is out of range (expected < " +
                                          std::to_string(ctx.model.samplers.size()) + " samplers)");
        ref.wrapS = wrapOf(ctx.model.samplers[tex.sampler].wrapS);
        ref.wrapT = wrapOf(ctx.model.samplers[tex.sampler].wrapT);
    }
    ref.texCoord = info.texCoord;
    auto ext = info.extensions.find("KHR_texture_transform");
    if (ext != info.extensions.end()) {
        const tinygltf::Value& t = ext->second;
        ref.transform = textureTransform({numberOr(t, "offset", 0, 0.0), numberOr(t, "offset", 1, 0.0)},
                                         static_cast<float>(numberOr(t, "rotation", -1, 0.0)),
                                         {numberOr(t, "scale", 0, 1.0), numberOr(t, "scale", 1, 1.0)});
        if (t.IsObject() && t.Has("texCoord") && t.Get("texCoord").IsInt())
            ref.texCoord = t.Get("texCoord").GetNumberAsInt();
    }
    if (ref.texCoord < 0 || ref.texCoord > 1) {
        warnings.push_back(where + " uses TEXCOORD_" + std::to_string(ref.texCoord) +
                           "; only sets 0 and 1 are "
                           "supported, using TEXCOORD_0");
        ref.texCoord = 0;
    }
    ref.image = scene.images[tex.source].rgba.empty() ? -1 : tex.source;
    return ref;
}

}  // namespace

void convertMaterials(const GltfContext& ctx, Scene& scene, std::vector<std::string>& warnings) {
    for (std::size_t i = 0; i < ctx.model.materials.size(); ++i) {
        const tinygltf::Material& src = ctx.model.materials[i];
        const std::string where = "materials[" + std::to_string(i) + "]";
        Material m;
        m.name = src.name.empty() ? "material " + std::to_string(i) : src.name;
        const auto& f = src.pbrMetallicRoughness.baseColorFactor;
        if (f.size() == 4)
            for (int k = 0; k < 4; ++k) {
                if (!std::isfinite(f[k]))
                    ctx.fail(where + ".pbrMetallicRoughness.baseColorFactor", "expected finite numbers");
                m.baseColorFactor[k] = static_cast<float>(f[k]);
            }
        if (src.pbrMetallicRoughness.baseColorTexture.index >= 0)
            m.baseColorTexture = convertTexture(ctx, scene, src.pbrMetallicRoughness.baseColorTexture,
                                                where + ".pbrMetallicRoughness.baseColorTexture", warnings);
        if (src.alphaMode == "MASK")
            m.alphaMode = AlphaMode::Mask;
        else if (src.alphaMode == "BLEND")
            m.alphaMode = AlphaMode::Blend;
        else if (src.alphaMode != "OPAQUE" && !src.alphaMode.empty())
            ctx.fail(where + ".alphaMode", "expected \"OPAQUE\", \"MASK\" or \"BLEND\", got \"" + src.alphaMode + "\"");
        m.alphaCutoff = std::isfinite(src.alphaCutoff) ? static_cast<float>(src.alphaCutoff) : 0.5f;
        m.doubleSided = src.doubleSided;
        scene.materials.push_back(std::move(m));
    }
}

}  // namespace cavewall::scenes
