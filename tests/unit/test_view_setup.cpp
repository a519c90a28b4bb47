// The viewer's policy for a model file (velocity/view_setup.hpp): two-sided materials,
// the default light, the scene framed from a file, and why a frame is empty.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>

#include "velocity/error.hpp"
#include "velocity/view_setup.hpp"

namespace velocity {
namespace {

size_t count_lights(const Scene& scene, LightType type) {
  size_t n = 0;
  for (const Light& l : scene.lights) n += l.type == type;
  return n;
}

TEST(ViewSetup, EveryMaterialTwoSidedAndMeshesWithoutOneGetOne) {
  Model model;
  auto with = std::make_shared<Mesh>(make_cube(1.0f));
  with->materials.resize(2);
  auto without = std::make_shared<Mesh>(make_cube(1.0f));
  without->materials.clear();
  model.nodes.push_back({"with", with, Mat4::identity(), -1});
  model.nodes.push_back({"without", without, Mat4::identity(), 0});
  model.nodes.push_back({"empty node", nullptr, Mat4::identity(), 0});
  make_two_sided(model);
  ASSERT_EQ(with->materials.size(), 2u);
  for (const Material& m : with->materials) EXPECT_TRUE(m.two_sided);
  ASSERT_EQ(without->materials.size(), 1u);
  EXPECT_TRUE(without->materials[0].two_sided);
}

TEST(ViewSetup, DefaultLightOnlyWhenTheSceneHasNoKeyLight) {
  Scene none;
  add_default_lights(none);
  EXPECT_EQ(count_lights(none, LightType::Ambient), 1u);
  EXPECT_EQ(count_lights(none, LightType::Directional), 1u);

  // 3D Studio files often bring only an ambient line: it is kept, a key light added.
  Scene ambient_only;
  ambient_only.lights.push_back(Light::ambient({0.5f, 0.5f, 0.5f}));
  add_default_lights(ambient_only);
  ASSERT_EQ(ambient_only.lights.size(), 2u);
  EXPECT_EQ(ambient_only.lights[0].color.x, 0.5f);
  EXPECT_EQ(ambient_only.lights[1].type, LightType::Directional);

  Scene lit;
  lit.lights.push_back(Light::point({0, 1, 0}, {1, 1, 1}));
  add_default_lights(lit);
  EXPECT_EQ(lit.lights.size(), 1u);
}

TEST(ViewSetup, SceneFromModelIsTwoSidedLitAndFramed) {
  const std::string path = std::string(VELOCITY_TEST_DATA) + "/models/duck.asc";
  Scene scene = scene_from_model(path, {}, false, 4.0f / 3.0f);
  ASSERT_FALSE(scene.objects().empty());
  for (const Object& o : scene.objects()) {
    if (!o.mesh) continue;
    for (const Material& m : o.mesh->materials) EXPECT_TRUE(m.two_sided);
  }
  EXPECT_GE(count_lights(scene, LightType::Directional) + count_lights(scene, LightType::Point), 1u);
  Renderer r(96, 72);
  r.options.threads = 1;
  const FrameStats& st = r.render(scene);
  EXPECT_GT(st.triangles_rasterized, 0u) << explain_empty_frame(st, false);

  Scene culled = scene_from_model(path, {}, true, 1.0f);
  for (const Object& o : culled.objects()) {
    if (!o.mesh) continue;
    for (const Material& m : o.mesh->materials) EXPECT_FALSE(m.two_sided);
  }
  EXPECT_THROW(scene_from_model(path + ".missing", {}, false, 1.0f), Error);
}

TEST(ViewSetup, EmptyFramesAreExplained) {
  FrameStats s;
  EXPECT_NE(explain_empty_frame(s, true).find("no triangles"), std::string::npos);
  s.objects = 1, s.triangles = 10, s.triangles_culled = 10;
  EXPECT_NE(explain_empty_frame(s, true).find("back faces"), std::string::npos);
  EXPECT_NE(explain_empty_frame(s, false).find("pixel centre"), std::string::npos);
  s.objects_culled = 1;
  EXPECT_NE(explain_empty_frame(s, true).find("outside the camera's view"), std::string::npos);
  s.objects_culled = 0, s.triangles_nonfinite = 10;
  EXPECT_NE(explain_empty_frame(s, true).find("NaN"), std::string::npos);
  s.triangles_rasterized = 1;
  EXPECT_EQ(explain_empty_frame(s, true), "");
}

// Issue 10, item 7: every model in ../shared/data shows something in the viewer's first
// frame (open meshes such as bumper.asc, floor.asc and plunger.asc included).
TEST(ViewSetup, EverySharedModelIsVisible) {
  namespace fs = std::filesystem;
  const fs::path root = VELOCITY_SHARED_DATA;
  if (!fs::exists(root / "models")) GTEST_SKIP() << "no " << root << " (the shared test data)";
  int checked = 0;
  for (const char* sub : {"models/asc", "models/plg"})
    for (const auto& entry : fs::directory_iterator(root / sub)) {
      if (!entry.is_regular_file()) continue;
      const std::string path = entry.path().string();
      Scene scene;
      try {
        scene = scene_from_model(path, {}, false, 4.0f / 3.0f);
      } catch (const Error&) {
        continue;  // files the loaders refuse (the invalid sample) have their own tests
      }
      Renderer r(96, 72);
      r.options.threads = 1;
      const FrameStats& st = r.render(scene);
      EXPECT_GT(st.triangles_rasterized, 0u) << path << ": " << explain_empty_frame(st, false);
      ++checked;
    }
  EXPECT_GT(checked, 40);
}

}  // namespace
}  // namespace velocity
