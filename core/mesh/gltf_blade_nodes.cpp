#include "mesh/gltf_blade_nodes.h"

#include <string>
#include <tiny_gltf.h>

namespace grass::core::gltf {

namespace {

bool markedAsBlades(const tinygltf::Node& node) {
    const std::string key(BLADE_GROUP_EXTRAS_KEY);
    if (!node.extras.Has(key))  // Has first: Get asserts an object
        return false;
    const tinygltf::Value& marker = node.extras.Get(key);
    return marker.IsBool() && marker.Get<bool>();
}

bool namedAsBlades(const tinygltf::Node& node) {
    constexpr std::string_view SUFFIX = " blades";
    return node.name.size() > SUFFIX.size() && node.name.ends_with(SUFFIX);
}

}  // namespace

std::vector<char> bladeGroupNodes(const tinygltf::Model& model) {
    std::vector<char> blades(model.nodes.size(), 0);
    std::vector<int> pending;
    const auto valid = [&](int node) { return node >= 0 && static_cast<std::size_t>(node) < blades.size(); };
    for (std::size_t n = 0; n < model.nodes.size(); ++n)
        if (markedAsBlades(model.nodes[n]))
            pending.push_back(static_cast<int>(n));
    for (const tinygltf::Scene& scene : model.scenes)
        if (scene.extras.Has("grass_runtime"))
            for (const int root : scene.nodes)
                if (valid(root) && namedAsBlades(model.nodes[static_cast<std::size_t>(root)]))
                    pending.push_back(root);
    // Down the hierarchy; each node once, so a cycle (refused later by the scene walk) ends here.
    while (!pending.empty()) {
        const int node = pending.back();
        pending.pop_back();
        if (!valid(node) || blades[static_cast<std::size_t>(node)])
            continue;
        blades[static_cast<std::size_t>(node)] = 1;
        for (const int child : model.nodes[static_cast<std::size_t>(node)].children)
            pending.push_back(child);
    }
    return blades;
}

}  // namespace grass::core::gltf
