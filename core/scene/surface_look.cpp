#include "scene/surface_look.h"

#include "export/source_material.h"

namespace grass::core {

SurfaceLook surfaceLookOf(const std::filesystem::path& file, bool meshHasUv) {
    SurfaceLook look;
    const SourceMaterial source = sourceMeshMaterial(file);
    const nlohmann::json& material = source.material;
    if (!material.is_object())
        return look;
    const nlohmann::json pbr = material.value("pbrMetallicRoughness", nlohmann::json::object());
    look.baseColor = glm::vec3(1.0f);
    if (const auto factor = pbr.find("baseColorFactor");
        factor != pbr.end() && factor->is_array() && factor->size() == 4)
        look.baseColor = glm::vec3((*factor)[0].get<float>(), (*factor)[1].get<float>(),
                                   (*factor)[2].get<float>());
    const auto slot = pbr.find("baseColorTexture");
    if (slot == pbr.end() || !slot->is_object())
        return look;
    const std::size_t index = slot->value("index", source.textures.size());
    if (index >= source.textures.size())
        return look;  // sourceMeshMaterial noted why it left the texture behind
    if (!meshHasUv) {
        look.notes.push_back(file.string() + ": the base-colour texture is not drawn: a primitive "
                                             "has no TEXCOORD_0, so the surface's UVs are generated");
        return look;
    }
    const SourceTexture& texture = source.textures[index];
    const std::string extension = texture.mimeType == "image/jpeg" ? ".jpg" : ".png";
    auto image = decodeRgba8Image(texture.bytes, file.string() + " base-colour texture", extension,
                                  MAX_SURFACE_TEXTURE_SIDE);
    if (!image) {
        look.notes.push_back(image.error().str() + " (the texture is not drawn)");
        return look;
    }
    look.baseTexture = std::move(*image);
    if (texture.sampler.is_object()) {
        look.wrapS = texture.sampler.value("wrapS", look.wrapS);
        look.wrapT = texture.sampler.value("wrapT", look.wrapT);
    }
    return look;
}

}  // namespace grass::core
