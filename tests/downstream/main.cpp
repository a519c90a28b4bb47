// Renders a cube with the installed library and checks that something was drawn.
#include <velocity/renderer.hpp>

#include <cstdio>

int main(int argc, char** argv) {
  velocity::Scene scene;
  auto cube = std::make_shared<const velocity::Mesh>(velocity::make_cube(1.0f));
  velocity::ObjectId id = scene.add_object("cube", cube);
  scene.object(id).transform.rotation = {0.5f, 0.6f, 0.0f};
  velocity::Renderer renderer(64, 48);
  const velocity::FrameStats& stats = renderer.render(scene);
  if (stats.triangles_rasterized == 0) return std::fprintf(stderr, "nothing drawn\n"), 1;
  velocity::Image image = renderer.color_image();
  if (argc > 1) velocity::write_image(argv[1], image);
  std::printf("downstream: %zu triangles drawn\n", stats.triangles_rasterized);
  return 0;
}
