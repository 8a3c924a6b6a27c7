// Internal to core/project/: what the *_json.cpp files of project.json's sections share beyond
// their tables (project/settings.h): the checks across the keys of a section, run once its keys
// are read, and the keyed paths of wind sources and colliders.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "project/json_reader.h"
#include "project/project.h"
#include "project/setting_io.h"
#include "project/settings.h"

namespace grass::core::json {

void checkCamera(Reader& reader, const Object& object, const CameraDesc& camera);
void checkSun(Reader& reader, const Object& object, const SunDesc& sun);
void checkLighting(Reader& reader, const Object& object, const GrassLightingDesc& lighting);
void checkRender(Reader& reader, const Object& object, const RenderSettings& render);
void checkWind(Reader& reader, const Object& object, const WindDesc& wind);
void checkSnow(Reader& reader, const Object& object, const SnowParams& snow);

// The keyed path a wind source or a collider follows (physics_json.cpp).
void readPath(Reader& reader, const Json& node, const std::string& pointer,
              std::vector<PathKey>& path);
Json pathJson(const std::vector<PathKey>& path);

// The setting of a keyed path the member chain reaches.
template <auto... Members>
constexpr settings::Setting<settings::detail::Owner<Members...>> pathSetting(
    settings::Setting<settings::detail::Owner<Members...>> row) {
    using S = settings::detail::Owner<Members...>;
    row.typeText = "array";
    return settings::custom<S>(
        row,
        [](Reader& reader, Object& object, std::string_view key, S& value) {
            if (const Json* node = object.find(key))
                readPath(reader, *node, object.pointerTo(key), (value .* ... .* Members));
        },
        [](const S& value) -> Json { return pathJson((value .* ... .* Members)); });
}

// billboard_json.cpp: the names of techniques and billboard animation modes.
inline constexpr std::array<std::string_view, 4> TECHNIQUE_NAMES{"blades", "billboards",
                                                                 "hybrid", "growth"};
inline constexpr std::array<std::string_view, 3> ANIMATION_NAMES{"per-cluster", "per-vertex",
                                                                 "per-object"};

}  // namespace grass::core::json
