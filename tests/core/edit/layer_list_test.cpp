// Layers as species (issue 27 item 2): the list edits keep names unique and the project valid,
// and a re-grown scene finds the layer each of its layers was.
#include <gtest/gtest.h>

#include "edit/layer_list.h"

namespace grass::core {
namespace {

std::vector<std::string> namesOf(const Project& project) {
    std::vector<std::string> names;
    for (const GrassLayer& layer : project.layers)
        names.push_back(layer.name);
    return names;
}

TEST(LayerList, AddDuplicateMoveRemoveKeepNamesUnique) {
    Project project;  // one layer, "grass"
    ASSERT_TRUE(addLayer(project));
    ASSERT_TRUE(addLayer(project));
    EXPECT_EQ(namesOf(project), (std::vector<std::string>{"grass", "grass 2", "grass 3"}));
    project.layers[0].rules.exclude = {"Clouds"};
    project.layers[0].densityMap = "maps/grass-density.png";
    ASSERT_TRUE(duplicateLayer(project, 0));
    EXPECT_EQ(project.layers[1].name, "grass copy");
    EXPECT_EQ(project.layers[1].rules, project.layers[0].rules);
    EXPECT_EQ(project.layers[1].densityMap, project.layers[0].densityMap);
    ASSERT_TRUE(duplicateLayer(project, 0));
    EXPECT_EQ(project.layers[1].name, "grass copy 2");
    ASSERT_TRUE(moveLayer(project, 0, false));
    EXPECT_EQ(namesOf(project)[0], "grass copy 2");
    EXPECT_EQ(namesOf(project)[1], "grass");
    EXPECT_FALSE(moveLayer(project, 0, true)) << "the first layer cannot go up";
    EXPECT_FALSE(moveLayer(project, project.layers.size() - 1, false));
    EXPECT_FALSE(renameLayer(project, 0, "grass")) << "another layer has the name";
    EXPECT_FALSE(renameLayer(project, 0, ""));
    EXPECT_TRUE(renameLayer(project, 0, "clover"));
    EXPECT_EQ(project.layers[0].name, "clover");
    while (project.layers.size() > 1)
        ASSERT_TRUE(removeLayer(project, 0));
    EXPECT_FALSE(removeLayer(project, 0)) << "a project keeps one layer";
    // The result is a project the format takes back.
    EXPECT_TRUE(parseProject(serializeProject(project), "layers.json").ok());
}

TEST(LayerList, TheListStopsAtTheFormatsLimit) {
    Project project;
    while (project.layers.size() < MAX_LAYERS)
        ASSERT_TRUE(addLayer(project));
    EXPECT_FALSE(addLayer(project));
    EXPECT_FALSE(duplicateLayer(project, 0));
}

TEST(LayerList, MatchingFollowsNamesThenIndices) {
    using Match = std::vector<std::optional<std::size_t>>;
    // Reordered: by name.
    EXPECT_EQ(matchLayers({"a", "b", "c"}, {"c", "a", "b"}), (Match{2, 0, 1}));
    // Removed and added: the removed one matches nothing, the new one is new.
    EXPECT_EQ(matchLayers({"a", "b", "c"}, {"a", "c", "d"}),
              (Match{0, 2, std::nullopt}));
    // Renamed in place: the index, since no layer keeps the old name.
    EXPECT_EQ(matchLayers({"a", "b"}, {"a", "bee"}), (Match{0, 1}));
    // A new layer at the index of one that moved is new, not the moved one.
    EXPECT_EQ(matchLayers({"a", "b"}, {"b", "new", "a"}), (Match{1, std::nullopt, 0}));
}

}  // namespace
}  // namespace grass::core
