// The searchable add menu's model (editor/add_search.hpp): every catalogue entry is an item, and
// the search finds them by name, category and description, best first.
#include "editor/add_search.hpp"

#include "scene/light_spec.hpp"
#include "sdf/operations.hpp"
#include "sdf/profiles.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

using namespace rmsc;
using namespace rmsc::editor;

namespace {

std::vector<std::string> namesOf(const std::vector<AddItem>& items, const std::vector<int>& found) {
    std::vector<std::string> names;
    for (int i : found)
        names.push_back(items[std::size_t(i)].name);
    return names;
}

bool has(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

} // namespace

TEST(AddSearch, ItemsComeFromEveryCatalogue) {
    const std::vector<AddItem>& items = addItems();
    const auto count = [&](AddCategory c) {
        return std::count_if(items.begin(), items.end(),
                             [&](const AddItem& i) { return i.category == c; });
    };
    EXPECT_EQ(count(AddCategory::Shape), std::ptrdiff_t(primitiveCatalogue().size()));
    EXPECT_EQ(count(AddCategory::ProfileShape), std::ptrdiff_t(profileSolidCatalogue().size()));
    EXPECT_EQ(count(AddCategory::Group), std::ptrdiff_t(operationCatalogue().size()));
    EXPECT_EQ(count(AddCategory::Light), std::ptrdiff_t(kLightTypes.size()));
    EXPECT_EQ(count(AddCategory::Mesh), 1);
    // In menu order, each with what it adds.
    EXPECT_EQ(items.front().name, primitiveCatalogue().front().name);
    EXPECT_EQ(std::get<PrimitiveId>(items.front().what), primitiveCatalogue().front().id);
    const auto gyroid = std::find_if(items.begin(), items.end(),
                                     [](const AddItem& i) { return i.name == "gyroid"; });
    ASSERT_NE(gyroid, items.end());
    EXPECT_EQ(std::get<PrimitiveId>(gyroid->what), PrimitiveId::Gyroid);
    EXPECT_FALSE(gyroid->description.empty());
    const auto revolution = std::find_if(items.begin(), items.end(),
                                         [](const AddItem& i) { return i.name == "revolution"; });
    ASSERT_NE(revolution, items.end());
    EXPECT_EQ(std::get<SdfProfileSolid>(revolution->what), SdfProfileSolid::Revolution);
    EXPECT_TRUE(std::holds_alternative<AddMeshFromFile>(items.back().what));
}

TEST(AddSearch, EmptyQueryListsEverythingInOrder) {
    const std::vector<AddItem>& items = addItems();
    const std::vector<int> all = searchAddItems(items, "  ");
    ASSERT_EQ(all.size(), items.size());
    for (std::size_t i = 0; i < all.size(); ++i)
        EXPECT_EQ(all[i], int(i));
}

TEST(AddSearch, FindsByNameCategoryAndDescription) {
    const std::vector<AddItem>& items = addItems();
    // "_" and case do not matter; every word must occur.
    EXPECT_EQ(namesOf(items, searchAddItems(items, "Round Box")),
              (std::vector<std::string>{"round_box"}));
    EXPECT_EQ(namesOf(items, searchAddItems(items, "round_box")),
              (std::vector<std::string>{"round_box"}));
    // A category: every light.
    const std::vector<std::string> lights = namesOf(items, searchAddItems(items, "light"));
    ASSERT_GE(lights.size(), 3u);
    EXPECT_EQ(std::vector<std::string>(lights.begin(), lights.begin() + 3),
              (std::vector<std::string>{"directional light", "point light", "spot light"}));
    // Words narrow: the smooth groups first.
    const std::vector<std::string> smooth = namesOf(items, searchAddItems(items, "smooth group"));
    ASSERT_GE(smooth.size(), 3u);
    EXPECT_EQ(
        std::vector<std::string>(smooth.begin(), smooth.begin() + 3),
        (std::vector<std::string>{"smooth_union", "smooth_subtraction", "smooth_intersection"}));
    EXPECT_FALSE(has(smooth, "union")) << "the plain union is not smooth";
    // A description match comes after the name matches: "ring" names no item, but the torus's
    // description says "a ring".
    const std::vector<std::string> ring = namesOf(items, searchAddItems(items, "ring"));
    EXPECT_TRUE(has(ring, "torus")) << "found by its description";
    // Names first: "cone" finds the cones by name before shapes that mention a cone.
    const std::vector<std::string> cone = namesOf(items, searchAddItems(items, "cone"));
    ASSERT_FALSE(cone.empty());
    EXPECT_EQ(cone.front(), "cone");
    const auto byDescription = std::find(cone.begin(), cone.end(), "solid_angle");
    const auto byName = std::find(cone.begin(), cone.end(), "round_cone");
    ASSERT_NE(byDescription, cone.end());
    ASSERT_NE(byName, cone.end());
    EXPECT_LT(byName, byDescription);
    EXPECT_TRUE(has(namesOf(items, searchAddItems(items, "gltf")), "glTF mesh from a file..."));
    EXPECT_TRUE(searchAddItems(items, "no such thing").empty());
}

TEST(AddSearch, HighlightStopsAtTheEnds) {
    EXPECT_EQ(moveHighlight(0, -1, 5), 0);
    EXPECT_EQ(moveHighlight(0, 1, 5), 1);
    EXPECT_EQ(moveHighlight(4, 1, 5), 4);
    EXPECT_EQ(moveHighlight(7, -1, 5), 4) << "a highlight past a shorter list comes back";
    EXPECT_EQ(moveHighlight(2, 1, 0), -1) << "nothing to highlight";
}
