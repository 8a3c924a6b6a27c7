#include "export/blade_instances.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

#include "util/assert.h"

namespace grass::core {

bool isLiveBlade(const Blade& blade) {
    return blade.h() > 0.0f && blade.w() > 0.0f;
}

glm::quat bladeRotation(glm::vec3 up, float theta) {
    const glm::vec3 y = glm::normalize(up);
    const glm::vec3 x = widthDirection(y, theta);
    // Right-handed: z = x × y, so the basis (x, y, z) is a proper rotation.
    const glm::vec3 z = glm::cross(x, y);
    // glm matrices are column-major: the columns are the images of +X, +Y, +Z.
    return glm::normalize(glm::quat_cast(glm::mat3(x, y, z)));
}

float bladeLeanRad(const Blade& blade) {
    const glm::vec3 up = glm::normalize(blade.up());
    const glm::vec3 front = glm::normalize(glm::cross(up, widthDirection(up, blade.theta())));
    const glm::vec3 chord = blade.v2() - blade.v0();
    const float lean = std::atan2(glm::dot(chord, front), glm::dot(chord, up));
    return std::clamp(lean, 0.0f, float(LEAN_BIN_COUNT - 1) * LEAN_BIN_STEP_RAD);
}

int leanBinOf(float leanRad) {
    const int bin = static_cast<int>(std::lround(leanRad / LEAN_BIN_STEP_RAD));
    return std::clamp(bin, 0, LEAN_BIN_COUNT - 1);
}

float leanBinRad(int bin) {
    return float(std::clamp(bin, 0, LEAN_BIN_COUNT - 1)) * LEAN_BIN_STEP_RAD;
}

int wiltBinOf(float wilt) {
    const int bin = static_cast<int>(std::lround(wilt * float(WILT_BIN_COUNT - 1)));
    return std::clamp(bin, 0, WILT_BIN_COUNT - 1);
}

float wiltBinValue(int bin) {
    return float(std::clamp(bin, 0, WILT_BIN_COUNT - 1)) / float(WILT_BIN_COUNT - 1);
}

std::vector<BladeInstance> bladeInstances(const LayerField& layer, int lod) {
    GRASS_ASSERT(lod >= 0 && lod <= 30);
    const std::size_t stride = std::size_t{1} << lod;
    const float widthScale = static_cast<float>(stride);
    const std::vector<Blade>& blades = layer.patched.blades;
    std::vector<BladeInstance> instances;
    instances.reserve(layer.liveBlades / stride + 1);
    std::size_t live = 0;
    for (std::size_t slot = 0; slot < blades.size(); ++slot) {
        const Blade& blade = blades[slot];
        if (!isLiveBlade(blade))
            continue;
        if (live++ % stride != 0)
            continue;
        const float wilt = slot < layer.wilt.size() ? layer.wilt[slot] : 0.0f;
        BladeInstance instance;
        instance.translation = blade.v0();
        instance.rotation = bladeRotation(blade.up(), blade.theta());
        instance.scale = glm::vec3(blade.w() * widthScale, blade.h(), blade.h());
        instance.stiffness = blade.s();
        instance.rootColor = glm::mix(layer.rootColor, layer.poorRootColor, wilt);
        instance.tipColor = glm::mix(layer.tipColor, layer.poorTipColor, wilt);
        instance.tipOffset = blade.v2() - blade.v0();
        if (slot < layer.shading.size()) {
            instance.blurredNormal = layer.shading[slot].blurredNormal();
            instance.ao = layer.shading[slot].ao();
            instance.water = layer.shading[slot].water();
        }
        instance.leanRad = bladeLeanRad(blade);
        instance.leanBin = leanBinOf(instance.leanRad);
        instance.wilt = wilt;
        instance.wiltBin = wiltBinOf(wilt);
        instances.push_back(instance);
    }
    return instances;
}

std::vector<InstanceGroup> groupInstances(const std::vector<BladeInstance>& instances) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const BladeInstance& b : instances) {
        lo = glm::min(lo, b.translation);
        hi = glm::max(hi, b.translation);
    }
    const glm::vec3 extent = hi - lo;
    const float edge = std::max(std::max(extent.x, std::max(extent.y, extent.z)) /
                                    float(CELLS_PER_AXIS),
                                1e-3f);
    std::map<std::tuple<int, int, int>, std::vector<std::uint32_t>> groups;
    for (std::uint32_t i = 0; i < instances.size(); ++i) {
        const glm::ivec3 c = glm::clamp(glm::ivec3(glm::floor((instances[i].translation - lo) / edge)),
                                        glm::ivec3(0), glm::ivec3(CELLS_PER_AXIS - 1));
        const int cell = (c.z * CELLS_PER_AXIS + c.y) * CELLS_PER_AXIS + c.x;
        groups[{cell, instances[i].leanBin, instances[i].wiltBin}].push_back(i);
    }
    std::vector<InstanceGroup> out;
    for (auto& [key, members] : groups)
        out.push_back({std::get<0>(key), std::get<1>(key), std::get<2>(key), std::move(members)});
    return out;
}

}  // namespace grass::core
