// The compile-time variants of the blade programs (shaders/blade*.{vert,tesc,tese,frag}): which
// preprocessor defines each feature compiles in, shared by the editor's renderer
// (render/scene_renderer.h) and the reference runtime (editor/runtime), so both name the same
// defines the shaders test. A feature is a variant rather than a uniform switch because software
// GL runs both sides of a uniform branch: code a frame does not use would still cost it
// (docs/rendering.md, "Program variants"). GL-free and header-only.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace grass::core {

struct BladeProgramVariant {
    bool tessellate = false;      // the tessellation stages, else the instanced strips
    bool lightPerVertex = false;  // GRASS_LIGHT_PER_VERTEX
    bool sunShadows = false;      // GRASS_SUN_SHADOWS
    bool fadeOut = false;         // GRASS_BLADE_FADE_OUT: the hybrid's distance fade
    bool lodBlend = false;        // GRASS_LOD_BLEND: the morph towards the next LOD
    bool snowTips = false;        // GRASS_SNOW_TIPS: the tips' snow while snow lies
    bool simpleLighting = false;  // GRASS_SIMPLE_LIGHTING: the wrapped Lambert, not SPEC §10

    // 0 .. BLADE_PROGRAM_VARIANTS − 1, one per combination.
    std::size_t index() const {
        return std::size_t(tessellate) | std::size_t(lightPerVertex) << 1 |
               std::size_t(sunShadows) << 2 | std::size_t(fadeOut) << 3 |
               std::size_t(lodBlend) << 4 | std::size_t(snowTips) << 5 |
               std::size_t(simpleLighting) << 6;
    }

    // The defines this variant compiles with, and a label naming them for GL debug output.
    std::vector<std::string> defines() const {
        std::vector<std::string> out;
        for (const Feature& feature : features())
            if (this->*feature.flag)
                out.emplace_back(feature.define);
        return out;
    }
    std::string label() const {
        std::string out = tessellate ? "blade tessellation" : "blade strips";
        for (const Feature& feature : features())
            if (this->*feature.flag)
                out += std::string(" (") + feature.name + ")";
        return out;
    }

private:
    struct Feature {
        bool BladeProgramVariant::*flag;
        const char* define;
        const char* name;
    };
    static const std::vector<Feature>& features() {
        static const std::vector<Feature> list{
            {&BladeProgramVariant::lightPerVertex, "GRASS_LIGHT_PER_VERTEX", "lit per vertex"},
            {&BladeProgramVariant::sunShadows, "GRASS_SUN_SHADOWS", "sun shadows"},
            {&BladeProgramVariant::fadeOut, "GRASS_BLADE_FADE_OUT", "fading out"},
            {&BladeProgramVariant::lodBlend, "GRASS_LOD_BLEND", "LOD blend"},
            {&BladeProgramVariant::snowTips, "GRASS_SNOW_TIPS", "snow tips"},
            {&BladeProgramVariant::simpleLighting, "GRASS_SIMPLE_LIGHTING", "simple lighting"},
        };
        return list;
    }
};

inline constexpr std::size_t BLADE_PROGRAM_VARIANTS = 128;

}  // namespace grass::core
