#include "project/setting_docs.h"

#include "project/setting_io.h"
#include "project/setting_text.h"
#include "project/settings.h"

namespace grass::core::settings {

namespace {

template <class S>
std::string markdownTable(std::span<const Setting<S>> table, const S& defaults) {
    std::string out = "| key | type | default | allowed |\n|---|---|---|---|\n";
    for (const Setting<S>& row : table) {
        std::string allowed = allowedText(row);
        if (!row.help.empty())
            allowed += (allowed.empty() ? "" : "; ") + std::string(row.help);
        // The default of a setting only some objects have (a mesh collider's scale) is the
        // value it takes where it applies.
        Setting<S> always = row;
        always.applies = nullptr;
        const json::Json value = settingJson(always, defaults);
        const std::string defaultText = !row.defaultText.empty() ? std::string(row.defaultText)
                                        : value.is_null()        ? "absent"
                                                                 : "`" + valueText(value) + "`";
        out += "| `" + std::string(row.key) + "` | " + typeText(row) + " | " + defaultText +
               " | " + allowed + " |\n";
    }
    return out;
}

}  // namespace

std::vector<DocTable> projectFormatTables() {
    return {
        {"the document", markdownTable(project(), Project{})},
        {"mesh", markdownTable(mesh(), MeshSource{})},
        {"layers", markdownTable(layer(), GrassLayer{})},
        {"layers/blade", markdownTable(blade(), BladeRanges{})},
        {"layers/growth", markdownTable(growth(), GrowthDesc{})},
        {"layers/rules", markdownTable(rules(), PlacementRules{})},
        {"layers/bending", markdownTable(bending(), BendingCues{})},
        {"cameras", markdownTable(camera(), CameraDesc{})},
        {"sun", markdownTable(sun(), SunDesc{})},
        {"lighting", markdownTable(lighting(), GrassLightingDesc{})},
        {"render", markdownTable(render(), RenderSettings{})},
        {"billboards", markdownTable(billboards(), BillboardDesc{})},
        {"physics", markdownTable(physics(), PhysicsParams{})},
        {"wind", markdownTable(wind(), WindDesc{})},
        {"colliders", markdownTable(collider(), ColliderDesc{})},
        {"snow", markdownTable(snow(), SnowParams{})},
    };
}

}  // namespace grass::core::settings
