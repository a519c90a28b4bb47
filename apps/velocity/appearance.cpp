// The appearance options render and bench share: the colour pipeline, tone mapping,
// exposure and shadows (RenderOptions; docs/appearance.md).
#include "commands.hpp"

#include <cmath>

#include "velocity/error.hpp"

namespace velocity::cli {

void add_appearance_options(CLI::App* cmd, AppearanceArgs& a) {
  cmd->add_option("--color", a.color,
                  "Colour pipeline: linear (sRGB decoded, lit in linear light, encoded), display (8-bit values as they "
                  "are, as OpenGL 1.x lights them), auto (linear when a material is PBR)")
      ->capture_default_str();
  cmd->add_option("--tone-map", a.tone_map, "Tone mapping in the linear pipeline: none|aces|neutral")->capture_default_str();
  cmd->add_option("--exposure", a.exposure, "Linear light is multiplied by this before tone mapping")->capture_default_str();
  cmd->add_flag("--shadows", a.shadows, "Shadow maps for the lights that cast shadows (directional, spot, point), bilinear PCF");
  cmd->add_option("--shadow-map-size", a.shadow_map_size, "Side of each shadow map in texels, 16..8192")->capture_default_str();
}

void apply_appearance(const AppearanceArgs& a, RenderOptions& o) {
  if (a.color == "auto") o.color = ColorPipeline::Auto;
  else if (a.color == "linear") o.color = ColorPipeline::Linear;
  else if (a.color == "display") o.color = ColorPipeline::Display;
  else throw Error("--color: expected linear|display|auto, got '" + a.color + "'");
  if (a.tone_map == "none") o.tone_map = ToneMap::None;
  else if (a.tone_map == "aces") o.tone_map = ToneMap::Aces;
  else if (a.tone_map == "neutral") o.tone_map = ToneMap::KhronosNeutral;
  else throw Error("--tone-map: expected none|aces|neutral, got '" + a.tone_map + "'");
  if (!(std::isfinite(a.exposure) && a.exposure >= 0))
    throw Error("--exposure: expected a finite number >= 0, got " + std::to_string(a.exposure));
  o.exposure = a.exposure;
  if (a.shadow_map_size < 16 || a.shadow_map_size > 8192)
    throw Error("--shadow-map-size: expected 16..8192, got " + std::to_string(a.shadow_map_size));
  o.shadows = a.shadows;
  o.shadow_map_size = a.shadow_map_size;
}

}  // namespace velocity::cli
