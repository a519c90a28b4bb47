// The GLSL sources. Each block says which CPU code it mirrors.
#include "shaders.hpp"

#include <vector>

#include "velocity/error.hpp"

namespace velocity::gpu {

// shading/lighting.hpp: light() with detail::add_light<Highlight::Phong> and
// detail::point_light, and apply(). Same terms, same order, same cut-off of the
// highlight below Specular::cutoff, same attenuation floor (1e-6).
const char* const kLightingGlsl = R"(
uniform vec3 u_ambient;
uniform int u_directional_count;
uniform vec3 u_directional_to_light[16];
uniform vec3 u_directional_color[16];
uniform int u_point_count;
uniform vec3 u_point_position[16];
uniform vec3 u_point_color[16];
uniform vec3 u_point_attenuation[16];  // constant, linear, quadratic
uniform vec3 u_point_falloff[16];      // inverse square (0 or 1), 1 / range^4 (0: no range), spot (0 or 1)
uniform vec3 u_point_spot_axis[16];    // unit, eye space: where a spot points
uniform vec2 u_point_spot_cone[16];    // the cone's scale and offset (shading::detail::spot_cone)
uniform vec3 u_specular;               // ks, exponent, cutoff

struct Terms { vec3 diffuse; vec3 specular; };

// shading/shadow.hpp: visibility() and map_visibility(), step for step: the lookup point
// moved kNormalOffset texels along the normal and kLightOffset towards the light (a
// texel's world size at the point), projected into the light's map, and the bilinear
// percentage-closer filter of the four texels around it (window depth, LESS as drawn);
// outside a map: lit; N.L <= 0: in shadow. A point light's cube picks its face as the
// CPU does. The maps are the layers of one depth texture, row 0 the CPU's row 0 (drawn
// with the frame's flipped projection), read with texelFetch: the filter is this code's,
// not the driver's, so that both backends weigh the same texels the same way.
const float kNormalOffset = 2.0, kLightOffset = 1.0;
uniform bool u_shadows;
uniform int u_directional_shadow[16];  // the light's shadow (an index into u_shadow_*), -1: none
uniform int u_point_shadow[16];
uniform int u_shadow_first[4];         // its first map (a layer of u_shadow_maps)
uniform int u_shadow_faces[4];         // 1, or a point light's 6 (+x, -x, +y, -y, +z, -z)
uniform vec3 u_shadow_position[4];     // a cube's light, eye space
uniform mat4 u_shadow_eye_to_clip[24]; // per map: the camera's eye space to the light's clip space
uniform vec2 u_shadow_texel[24];       // per map: a texel's world size, perspective (0 or 1)
uniform int u_shadow_size;
uniform sampler2DArray u_shadow_maps;

float shadow_lit(int map, int x, int y, float z) {
  return z <= texelFetch(u_shadow_maps, ivec3(x, y, map), 0).r ? 1.0 : 0.0;
}

float map_visibility(int map, vec3 p, vec3 n, vec3 to_light) {
  mat4 m = u_shadow_eye_to_clip[map];
  float w0 = (m * vec4(p, 1.0)).w;
  float texel = u_shadow_texel[map].y > 0.5 ? u_shadow_texel[map].x * w0 : u_shadow_texel[map].x;
  vec3 q = p + n * (kNormalOffset * texel) + to_light * (kLightOffset * texel);
  vec4 c = m * vec4(q, 1.0);
  if (!(c.w > 0.0)) return 1.0;
  float s = float(u_shadow_size);
  float x = (c.x / c.w * 0.5 + 0.5) * s, y = (0.5 - 0.5 * c.y / c.w) * s, z = c.z / c.w * 0.5 + 0.5;
  if (!(x >= 0.0 && x < s && y >= 0.0 && y < s && z <= 1.0)) return 1.0;
  float gx = x - 0.5, gy = y - 0.5, fx0 = floor(gx), fy0 = floor(gy);
  float fx = gx - fx0, fy = gy - fy0;
  int x0 = max(int(fx0), 0), y0 = max(int(fy0), 0);
  int x1 = min(int(fx0) + 1, u_shadow_size - 1), y1 = min(int(fy0) + 1, u_shadow_size - 1);
  float l00 = shadow_lit(map, x0, y0, z), l10 = shadow_lit(map, x1, y0, z);
  float l01 = shadow_lit(map, x0, y1, z), l11 = shadow_lit(map, x1, y1, z);
  float top = l00 + (l10 - l00) * fx, bottom = l01 + (l11 - l01) * fx;
  return top + (bottom - top) * fy;
}

int cube_face(vec3 v) {
  vec3 a = abs(v);
  if (a.x >= a.y && a.x >= a.z) return v.x >= 0.0 ? 0 : 1;
  if (a.y >= a.z) return v.y >= 0.0 ? 2 : 3;
  return v.z >= 0.0 ? 4 : 5;
}

float visibility(int k, vec3 p, vec3 n, vec3 to_light) {
  if (!(dot(n, to_light) > 0.0)) return 0.0;
  int first = u_shadow_first[k];
  if (u_shadow_faces[k] == 1) return map_visibility(first, p, n, to_light);
  // The face of the point the bias moves the lookup to.
  int face = first + cube_face(p - u_shadow_position[k]);
  float texel = u_shadow_texel[face].x * (u_shadow_eye_to_clip[face] * vec4(p, 1.0)).w;
  vec3 q = p + n * (kNormalOffset * texel) + to_light * (kLightOffset * texel);
  return map_visibility(first + cube_face(q - u_shadow_position[k]), p, n, to_light);
}

// A light's visibility factor: 1 where it casts no shadow.
float directional_visibility(int i, vec3 p, vec3 n) {
  return u_shadows && u_directional_shadow[i] >= 0 ? visibility(u_directional_shadow[i], p, n, u_directional_to_light[i]) : 1.0;
}
float point_visibility(int i, vec3 p, vec3 n, vec3 to_light) {
  return u_shadows && u_point_shadow[i] >= 0 ? visibility(u_point_shadow[i], p, n, to_light) : 1.0;
}

void add_light(inout Terms t, vec3 n, vec3 to_light, vec3 color, vec3 to_eye) {
  float nl = dot(n, to_light);
  t.diffuse += color * max(nl, 0.0);
  if (u_specular.x > 0.0) {
    vec3 r = n * (2.0 * nl) - to_light;
    float rv = dot(r, to_eye);
    if (rv > u_specular.z) t.specular += color * (u_specular.x * pow(rv, u_specular.y));
  }
}

// shading::detail::punctual: point light i seen from p (falloff, range window, spot
// cone, in that order); sets the unit direction to the light (along n at the light).
float punctual(int i, vec3 p, vec3 n, out vec3 to_light) {
  vec3 v = u_point_position[i] - p;
  float dist = length(v);
  vec3 a = u_point_attenuation[i], f = u_point_falloff[i];
  float d2 = dot(v, v);
  float att = f.x > 0.5 ? 1.0 / max(d2, 0.01) : 1.0 / max(a.x + (a.z * dist + a.y) * dist, 1e-6);
  to_light = d2 > 0.0 ? v / dist : n;
  if (f.y > 0.0) {
    float w = clamp(1.0 - d2 * d2 * f.y, 0.0, 1.0);
    att *= w * w;
  }
  if (f.z > 0.5) {
    float c = clamp(-dot(u_point_spot_axis[i], to_light) * u_point_spot_cone[i].x + u_point_spot_cone[i].y, 0.0, 1.0);
    att *= c * c;
  }
  return att;
}

Terms light(vec3 n, vec3 p) {
  Terms t = Terms(u_ambient, vec3(0.0));
  vec3 to_eye = u_specular.x > 0.0 ? normalize(-p) : vec3(0.0);
  for (int i = 0; i < u_directional_count; ++i)
    add_light(t, n, u_directional_to_light[i], u_directional_color[i] * directional_visibility(i, p, n), to_eye);
  for (int i = 0; i < u_point_count; ++i) {
    vec3 to_light;
    float att = punctual(i, p, n, to_light);
    att *= point_visibility(i, p, n, to_light);
    add_light(t, n, to_light, u_point_color[i] * att, to_eye);
  }
  return t;
}

vec3 apply(Terms t, vec3 base) { return base * t.diffuse + t.specular; }
)";

// raster/shade_pbr-inl.h's BRDF (glTF 2.0 Appendix B) for one surface point, the same
// terms in the same order with the same clamps: roughness at least 0.045, N.V at
// least 1e-4, N.H and V.H saturated, the floors of D's and Vis's denominators; the
// diffuse share 1 - F of the dielectric's Fresnel; the specular lobe times the
// multiple-scattering factor M = 1 + f0 (1 / E - 1), E read bilinearly from the same
// table (u_ggx_albedo: shading/ggx_albedo.hpp's, uploaded with the lights); the
// ambient is a uniform radiance times c_diff, darkened by occlusion. Lights are
// kLightingGlsl's uniforms and punctual().
const char* const kPbrGlsl = R"(
const float kInvPi = 0.318309886;
uniform float u_ggx_albedo[256];  // 16 x 16: row j for N.V, column i for roughness

float ggx_albedo(float rough, float nv) {
  float x = clamp(rough * 16.0 - 0.5, 0.0, 15.0), y = clamp(nv * 16.0 - 0.5, 0.0, 15.0);
  float lx = min(floor(x), 14.0), ly = min(floor(y), 14.0);
  int at = int(ly) * 16 + int(lx);
  float fx = x - lx, fy = y - ly;
  float top = mix(u_ggx_albedo[at], u_ggx_albedo[at + 1], fx);
  float bottom = mix(u_ggx_albedo[at + 16], u_ggx_albedo[at + 17], fx);
  return mix(top, bottom, fy);
}

vec3 pbr_add_light(vec3 n, vec3 view, vec3 l, vec3 radiance, vec3 cdiff, vec3 f0, vec3 ms, float a2, float nv,
                   float nv_term) {
  float nl = dot(n, l);
  if (nl <= 0.0) return vec3(0.0);
  vec3 h = normalize(l + view);
  float nh = clamp(dot(n, h), 0.0, 1.0), vh = clamp(dot(view, h), 0.0, 1.0);
  float q = 1.0 - vh, q2 = q * q, q5 = q2 * q2 * q;
  float dn = 1.0 - nh * nh * (1.0 - a2);  // (N.H)^2 (a^2 - 1) + 1
  float dist = a2 * kInvPi / max(dn * dn, 1e-12);
  float den = nl * nv_term + nv * sqrt(nl * nl * (1.0 - a2) + a2);
  float spec = 0.5 * dist / max(den, 1e-12);
  vec3 f = (f0 + (1.0 - f0) * q5) * ms;  // Schlick, times M
  float diffuse_share = 0.96 - 0.96 * q5;  // 1 - F of the dielectric
  return (f * spec + diffuse_share * cdiff * kInvPi) * radiance * nl;
}

// n and view unit, p the eye-space position; ao the occlusion factor (1: none).
vec3 pbr_light(vec3 n, vec3 view, vec3 p, vec3 base, float metallic, float roughness, float ao) {
  float metal = clamp(metallic, 0.0, 1.0);
  float rough = min(max(roughness, 0.045), 1.0);
  float a = rough * rough, a2 = a * a;
  float dielectric = 1.0 - metal;
  vec3 cdiff = base * dielectric;
  vec3 f0 = base * metal + 0.04 * dielectric;
  float nv = max(dot(n, view), 1e-4);
  float nv_term = sqrt(nv * nv * (1.0 - a2) + a2);
  vec3 c = cdiff * u_ambient * ao;
  vec3 ms = vec3(1.0);
  if (u_directional_count + u_point_count > 0) ms = 1.0 + f0 * (1.0 / ggx_albedo(rough, nv) - 1.0);
  for (int i = 0; i < u_directional_count; ++i)
    c += pbr_add_light(n, view, u_directional_to_light[i], u_directional_color[i] * directional_visibility(i, p, n), cdiff,
                       f0, ms, a2, nv, nv_term);
  for (int i = 0; i < u_point_count; ++i) {
    vec3 to_light;
    float att = punctual(i, p, n, to_light);
    att *= point_visibility(i, p, n, to_light);
    c += pbr_add_light(n, view, to_light, u_point_color[i] * att, cdiff, f0, ms, a2, nv, nv_term);
  }
  return c;
}
)";

// The frame's colour pipeline (geometry::pipeline_color, raster/output-inl.h):
// to_pipeline() puts a vertex or face colour into the frame's space; finish() turns
// light into the output's values: as they are (Display, clamped), or exposure, tone
// map (ACES as three.js, Khronos PBR Neutral) and the sRGB encoding (Linear); or the
// encoding alone (the flat kernel's packed colour, mesh_job.cpp's pack_flat).
const char* const kColorGlsl = R"(
uniform int u_color_convert;  // 0 as it is, 1 sRGB to linear, 2 linear to sRGB
uniform int u_output;         // 0 display, 1 linear (exposure, tone map, encode), 2 encode only
uniform float u_exposure;
uniform int u_tone_map;       // ToneMap: 0 none, 1 ACES, 2 Khronos PBR Neutral

vec3 srgb_to_linear(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(pow((c + 0.055) / 1.055, vec3(2.4)), c / 12.92, lessThanEqual(c, vec3(0.04045)));
}
vec3 linear_to_srgb(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, c * 12.92, lessThanEqual(c, vec3(0.0031308)));
}
vec3 to_pipeline(vec3 c) {
  if (u_color_convert == 1) return srgb_to_linear(c);
  if (u_color_convert == 2) return linear_to_srgb(c);
  return c;
}

vec3 aces_fit(vec3 v) { return (v * (v + 0.0245786) - 0.000090537) / (v * (0.983729 * v + 0.4329510) + 0.238081); }
vec3 tone_map_aces(vec3 c) {
  c *= 1.0 / 0.6;
  vec3 t = vec3(dot(vec3(0.59719, 0.35458, 0.04823), c), dot(vec3(0.07600, 0.90834, 0.01566), c),
                dot(vec3(0.02840, 0.13383, 0.83777), c));
  t = aces_fit(t);
  t = vec3(dot(vec3(1.60475, -0.53108, -0.07367), t), dot(vec3(-0.10208, 1.10813, -0.00605), t),
           dot(vec3(-0.00327, -0.07276, 1.07602), t));
  return clamp(t, 0.0, 1.0);
}
vec3 tone_map_neutral(vec3 c) {
  const float kStart = 0.8 - 0.04, kDesaturation = 0.15, kD = 1.0 - kStart;
  float x = min(c.r, min(c.g, c.b));
  float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
  c -= offset;
  float peak = max(c.r, max(c.g, c.b));
  if (peak < kStart) return c;
  float new_peak = 1.0 - kD * kD / (peak + kD - kStart);
  float g = 1.0 - 1.0 / (kDesaturation * (peak - new_peak) + 1.0);
  vec3 s = c * (new_peak / max(peak, 1e-6));
  return mix(s, vec3(new_peak), g);
}
vec3 finish(vec3 c) {
  if (u_output == 0) return clamp(c, 0.0, 1.0);
  if (u_output == 1) {
    c *= u_exposure;
    if (u_tone_map == 1) c = tone_map_aces(c);
    else if (u_tone_map == 2) c = tone_map_neutral(c);
  }
  return linear_to_srgb(c);
}
)";

// Lines drawn by the CPU's rule rather than the driver's (pGL's line batches and
// wireframe meshes): raster/coverage-inl.h's line_blocks (GL's diamond exit along the
// major axis, the ties on pixel boundaries where Mesa puts them, `width` pixels across)
// and triangle/setup.cpp's setup_line (values at the pixel centre's projection onto the
// segment), so that every driver lights the pixels the CPU and Mesa light. The geometry
// stage clips each segment, maps its ends to window pixels (y down, as the CPU's: the
// image is drawn upside down; snapped to 1/256 as the CPU's vertices are) and covers it
// with a quad (kLineQuadGlsl); the fragment stage keeps the pixels the rule lights
// (kLineRuleGlsl).
const char* const kLineQuadGlsl = R"(
uniform vec4 u_viewport;     // x, y (from the top), width, height: pixels
uniform vec2 u_depth_range;  // near, far
flat out vec4 l_ends;        // x0, y0, x1, y1: window pixels, y down
flat out vec4 l_shape;       // width, x-major (0 or 1), window depth at each end
flat out vec2 l_inv_w;

void line_vertex(float t0, float t1);  // the stage's own outputs at a vertex of the quad

// Cuts the segment [t0, t1] of the line where distance d (at each end) is >= 0.
bool cut(float d0, float d1, inout float t0, inout float t1) {
  if (d0 < 0.0 && d1 < 0.0) return false;
  if (d0 < 0.0) t0 = max(t0, d0 / (d0 - d1));
  else if (d1 < 0.0) t1 = min(t1, d0 / (d0 - d1));
  return t0 <= t1;
}

// The segment p0 p1 from t0 to t1 (already cut to any other planes) cut to the near
// and far planes, its ends in window pixels, covered by a quad; false: nothing left.
bool emit_line(vec4 p0, vec4 p1, float t0, float t1, float width) {
  if (!cut(p0.w + p0.z, p1.w + p1.z, t0, t1) || !cut(p0.w - p0.z, p1.w - p1.z, t0, t1)) return false;
  vec4 q0 = mix(p0, p1, t0), q1 = mix(p0, p1, t1);
  if (!(q0.w > 0.0 && q1.w > 0.0)) return false;
  vec3 n0 = q0.xyz / q0.w, n1 = q1.xyz / q1.w;
  vec2 w0 = u_viewport.xy + (n0.xy * 0.5 + 0.5) * u_viewport.zw, w1 = u_viewport.xy + (n1.xy * 0.5 + 0.5) * u_viewport.zw;
  w0 = floor(w0 * 256.0 + 0.5) / 256.0, w1 = floor(w1 * 256.0 + 0.5) / 256.0;
  vec2 d = w1 - w0;
  if (!(dot(d, d) > 0.0)) return false;
  bool x_major = abs(d.x) >= abs(d.y);
  // A quad a pixel and a half longer at each end, and the width and four pixels wider
  // (every pixel the rule lights has its centre inside), in the viewport's terms.
  vec2 along = normalize(d), across = x_major ? vec2(0.0, 1.0) : vec2(1.0, 0.0);
  float reach = width * 0.5 + 2.0;
  vec2 a = w0 - along * 1.5, b = w1 + along * 1.5;
  vec2 corners[4] = vec2[4](a - across * reach, a + across * reach, b - across * reach, b + across * reach);
  for (int i = 0; i < 4; ++i) {
    l_ends = vec4(w0, w1);
    l_shape = vec4(width, x_major ? 1.0 : 0.0, mix(u_depth_range.x, u_depth_range.y, n0.z * 0.5 + 0.5),
                   mix(u_depth_range.x, u_depth_range.y, n1.z * 0.5 + 0.5));
    l_inv_w = vec2(1.0 / q0.w, 1.0 / q1.w);
    line_vertex(t0, t1);
    gl_Position = vec4((corners[i] - u_viewport.xy) / u_viewport.zw * 2.0 - 1.0, 0.0, 1.0);
    EmitVertex();
  }
  EndPrimitive();
  return true;
}
)";

const char* const kLineRuleGlsl = R"(
flat in vec4 l_ends;
flat in vec4 l_shape;
flat in vec2 l_inv_w;

// line_blocks' rule for the pixel at column x, row y (y down).
bool line_covers(int x, int y) {
  bool xm = l_shape.y > 0.5;
  float a0 = xm ? l_ends.x : l_ends.y, a1 = xm ? l_ends.z : l_ends.w;
  float b0 = xm ? l_ends.y : l_ends.x, b1 = xm ? l_ends.w : l_ends.z;
  float len = a1 - a0;
  int first = len >= 0.0 ? int(ceil(a0 - 0.5)) : int(floor(a1 - 0.5)) + 1;
  int last = len >= 0.0 ? int(ceil(a1 - 0.5)) - 1 : int(floor(a0 - 0.5));
  int a = xm ? x : y, b = xm ? y : x;
  if (a < first || a > last) return false;
  bool tie_up = xm && (b1 - b0) * len > 0.0;
  bool skip_tied_start = len < 0.0 && (xm ? b1 - b0 >= 0.0 : b1 - b0 < 0.0);
  float s = len != 0.0 ? (float(a) + 0.5 - a0) / len : 0.0;
  float v = b0 + s * (b1 - b0);
  float up = ceil(v);
  int centre = int(up) - 1 + (tie_up && up == v ? 1 : 0);
  if (skip_tied_start && up == v && float(a) + 0.5 == a0) return false;
  int width = int(l_shape.x), half_width = (width - 1) / 2;
  return b >= centre - half_width && b <= centre - half_width + width - 1;
}

// Where this fragment's pixel centre projects onto the segment (0 at its start).
float line_t() {
  vec2 d = l_ends.zw - l_ends.xy;
  return dot(floor(gl_FragCoord.xy) + 0.5 - l_ends.xy, d) / dot(d, d);
}
)";

namespace {

const char* const kVersion = "#version 330 core\n";

// What both mesh vertex shaders read: the mesh's arrays and its matrices.
const char* const kMeshVertexInputs = R"(
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec3 a_color;
uniform mat4 u_mvp;
uniform mat4 u_model_view;
uniform mat4 u_normal_matrix;
)";

// The vertex stage (geometry/vertex_stage.cpp): clip position, eye position and unit
// eye normal; for Gouraud, the light terms of both sides (the back's for two-sided).
const char* const kMeshVertex = R"(
uniform bool u_vertex_light;
uniform bool u_two_sided;
out V {
  vec3 object_position;
  vec3 eye;
  vec3 normal;
  vec2 uv;
  vec3 color;
  vec3 diffuse;
  vec3 specular;
  vec3 back_diffuse;
  vec3 back_specular;
} v;
void main() {
  gl_Position = u_mvp * vec4(a_position, 1.0);
  v.object_position = a_position;
  v.eye = (u_model_view * vec4(a_position, 1.0)).xyz;
  v.normal = normalize((u_normal_matrix * vec4(a_normal, 0.0)).xyz);
  v.uv = a_uv;
  v.color = a_color;
  v.diffuse = vec3(0.0), v.specular = vec3(0.0), v.back_diffuse = vec3(0.0), v.back_specular = vec3(0.0);
  if (u_vertex_light) {
    Terms t = light(v.normal, v.eye);
    v.diffuse = t.diffuse, v.specular = t.specular;
    if (u_two_sided) {
      t = light(-v.normal, v.eye);
      v.back_diffuse = t.diffuse, v.back_specular = t.specular;
    }
  }
}
)";

// Gouraud and Phong without per-face colours need nothing per face: this vertex shader
// does the geometry shader's per-corner work itself (the same lines), and the program
// has no geometry stage, which software drivers run far slower.
const char* const kMeshVertexDirect = R"(
uniform int u_mode;
uniform int u_base_source;
uniform bool u_lit;
uniform bool u_unlit_vertex_colors;
uniform bool u_uv_from_env;
uniform bool u_two_sided;
uniform vec3 u_material_color;
out G {
  INTERP vec3 eye;
  INTERP vec3 normal;
  INTERP vec2 uv;
  INTERP vec3 front;
  INTERP vec3 back;
} g;
flat out vec3 g_flat_front;
flat out vec3 g_flat_back;
void main() {
  gl_Position = u_mvp * vec4(a_position, 1.0);
  g.eye = (u_model_view * vec4(a_position, 1.0)).xyz;
  g.normal = normalize((u_normal_matrix * vec4(a_normal, 0.0)).xyz);
  vec3 base = u_unlit_vertex_colors || u_base_source == 2 ? to_pipeline(a_color) : u_material_color;
  g.front = g.back = base;
  if (u_mode == 1 && u_lit) {
    Terms t = light(g.normal, g.eye);
    g.front = clamp(base * t.diffuse + t.specular, 0.0, 1.0);
    if (u_two_sided) {
      t = light(-g.normal, g.eye);
      g.back = clamp(base * t.diffuse + t.specular, 0.0, 1.0);
    }
  }
  g.uv = u_uv_from_env ? vec2(0.5) + vec2(0.5, -0.5) * g.normal.xy : a_uv;
  g_flat_front = g_flat_back = vec3(1.0);
}
)";

// The triangle stage (triangle/mesh_job.cpp: corner, flat_color): per face, the base
// colour (material, face or vertex colours), the flat colour lit by the face normal at
// the centroid, Gouraud's clamped corner colours, the per-vertex sphere-map uv.
const char* const kMeshGeometry = R"(
layout(triangles) in;
// PRIMITIVE 0: the triangle; 1: its edges (Shading::Wireframe); 2: its corners (Points).
// Edges and corners are made here, not by glPolygonMode (llvmpipe draws a geometry
// shader's triangles in line mode wrongly), so back faces are culled here for them.
#if PRIMITIVE == 0
layout(triangle_strip, max_vertices = 3) out;
#elif PRIMITIVE == 1
layout(triangle_strip, max_vertices = 12) out;  // a quad per edge (kLineQuadGlsl)
#else
layout(points, max_vertices = 3) out;
#endif
uniform bool u_cull;
uniform float u_point_size;  // Points: RenderOptions::point_size in samples (mesh_job.cpp's point_size)
in V {
  vec3 object_position;
  vec3 eye;
  vec3 normal;
  vec2 uv;
  vec3 color;
  vec3 diffuse;
  vec3 specular;
  vec3 back_diffuse;
  vec3 back_specular;
} v[];
uniform int u_mode;
uniform int u_base_source;
uniform bool u_lit;
uniform bool u_unlit_vertex_colors;  // Shading::Unlit with vertex colours: they win
uniform bool u_uv_from_env;
uniform bool u_two_sided;
uniform vec3 u_material_color;
uniform int u_face_base;
uniform bool u_face_order;           // painter's mode: faces drawn in u_order's order
uniform samplerBuffer u_face_colors;
uniform isamplerBuffer u_order;
uniform mat4 u_model_view;
uniform mat4 u_normal_matrix;
out G {
  INTERP vec3 eye;
  INTERP vec3 normal;
  INTERP vec2 uv;
  INTERP vec3 front;
  INTERP vec3 back;
} g;
flat out vec3 g_flat_front;
flat out vec3 g_flat_back;

vec3 base_color(int i, int face) {
  if (u_base_source == 1) return to_pipeline(texelFetch(u_face_colors, face).rgb);
  if (u_base_source == 2) return to_pipeline(v[i].color);
  return u_material_color;
}

#if PRIMITIVE == 1
vec3 line_front, line_back;
void line_vertex(float t0, float t1) {
  g.eye = vec3(0.0), g.normal = vec3(0.0, 0.0, 1.0), g.uv = vec2(0.0);
  g.front = g.back = line_front;
  g_flat_front = line_front, g_flat_back = line_back;
}
#endif

void main() {
  int face = u_face_base + gl_PrimitiveIDIn;
  if (u_face_order) face = texelFetch(u_order, face).r;
  vec3 flat_front = vec3(1.0), flat_back = vec3(1.0);
  if (u_mode == 0) {
    vec3 base = u_base_source == 2 ? to_pipeline((v[0].color + v[1].color + v[2].color) / 3.0) : base_color(0, face);
    vec3 n = normalize((u_normal_matrix * vec4(normalize(cross(v[1].object_position - v[0].object_position, v[2].object_position - v[0].object_position)), 0.0)).xyz);
    vec3 center = (u_model_view * vec4((v[0].object_position + v[1].object_position + v[2].object_position) / 3.0, 1.0)).xyz;
    flat_front = apply(light(n, center), base);
    if (u_two_sided) flat_back = apply(light(-n, center), base);
  } else if (u_mode == 3) {
    flat_front = flat_back = u_material_color;
  }
#if PRIMITIVE != 0
  // Facing as the CPU's homogeneous test (triangle/cull.hpp), in the flipped frame.
  vec4 p0 = gl_in[0].gl_Position, p1 = gl_in[1].gl_Position, p2 = gl_in[2].gl_Position;
  float det = determinant(mat3(p0.xyw, p1.xyw, p2.xyw));
#if PRIMITIVE == 2
  // A point cloud's points are triangles with one corner three times: no facing.
  bool cloud = v[0].object_position == v[1].object_position && v[1].object_position == v[2].object_position;
  if (u_cull && det >= 0.0 && !cloud) return;
#else
  if (u_cull && det >= 0.0) return;
#endif
#endif
#if PRIMITIVE == 1
  // The edges by the CPU's line rule (triangle/mesh_job.cpp's edges: each from corner
  // k to k + 1, one pixel wide), in the one colour of the draw.
  line_front = flat_front, line_back = flat_back;
  for (int k = 0; k < 3; ++k) emit_line(gl_in[k].gl_Position, gl_in[(k + 1) % 3].gl_Position, 0.0, 1.0, 1.0);
  return;
#endif
  for (int i = 0; i < 3; ++i) {
    vec3 base = u_unlit_vertex_colors ? to_pipeline(v[i].color) : base_color(i, face);
    g.front = g.back = base;
    if (u_mode == 1 && u_lit) {
      g.front = clamp(base * v[i].diffuse + v[i].specular, 0.0, 1.0);
      g.back = clamp(base * v[i].back_diffuse + v[i].back_specular, 0.0, 1.0);
    }
    g.eye = v[i].eye;
    g.normal = v[i].normal;
    g.uv = u_uv_from_env ? vec2(0.5) + vec2(0.5, -0.5) * v[i].normal.xy : v[i].uv;
    g_flat_front = flat_front, g_flat_back = flat_back;
    gl_Position = gl_in[i].gl_Position;
#if PRIMITIVE == 2
    gl_PointSize = u_point_size;
#endif
    EmitVertex();
#if PRIMITIVE == 2
    EndPrimitive();
#endif
  }
#if PRIMITIVE == 0
  EndPrimitive();
#endif
}
)";

// The pixel kernels (raster/shade_mesh-inl.h): Flat, FlatTex, Smooth, SmoothTex and
// the Phong family, and the object id of the draw; the output as the frame's pipeline
// says (finish: raster/output-inl.h).
const char* const kMeshFragment = R"(
in G {
  INTERP vec3 eye;
  INTERP vec3 normal;
  INTERP vec2 uv;
  INTERP vec3 front;
  INTERP vec3 back;
} g;
flat in vec3 g_flat_front;
flat in vec3 g_flat_back;
uniform int u_mode;
uniform bool u_two_sided;
uniform bool u_textured;
uniform bool u_env;
uniform bool u_uv_from_env;
uniform float u_env_mix;
uniform sampler2D u_texture;
uniform sampler2D u_env_map;
uniform uint u_object_id;
layout(location = 0) out vec4 o_color;
layout(location = 1) out uint o_id;
void main() {
#if PRIMITIVE == 1
  // (The image is drawn upside down: GL's rows are the CPU's.)
  if (!line_covers(int(floor(gl_FragCoord.x)), int(floor(gl_FragCoord.y)))) discard;
  gl_FragDepth = mix(l_shape.z, l_shape.w, line_t());
#endif
  bool back = u_two_sided && !gl_FrontFacing;
  vec3 c;
  if (u_mode == 0 || u_mode == 3) {
    c = back ? g_flat_back : g_flat_front;
    if (u_textured) c = clamp(c, 0.0, 1.0) * texture(u_texture, g.uv).rgb;  // the flat colour is packed first
  } else if (u_mode == 1) {
    c = back ? g.back : g.front;
    if (u_textured) c *= texture(u_texture, g.uv).rgb;
  } else {
    vec3 base = g.front;
    vec3 n = normalize(g.normal);
    if (back) n = -n;
    if (u_textured && !u_uv_from_env) base *= texture(u_texture, g.uv).rgb;
    if (u_env) base = mix(base, texture(u_env_map, vec2(0.5) + vec2(0.5, -0.5) * n.xy).rgb, u_env_mix);
    c = apply(light(n, g.eye), base);
  }
  o_color = vec4(finish(c), 1.0);
  o_id = u_object_id;
}
)";

GLuint compile(GLenum type, const std::string& source) {
  GLuint s = glCreateShader(type);
  const char* text = source.c_str();
  glShaderSource(s, 1, &text, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint n = 0;
    glGetShaderiv(s, GL_INFO_LOG_LENGTH, &n);
    std::vector<char> log(size_t(std::max(n, 1)));
    glGetShaderInfoLog(s, GLsizei(log.size()), nullptr, log.data());
    glDeleteShader(s);
    throw Error(std::string("the GPU backend's ") + (type == GL_VERTEX_SHADER ? "vertex" : type == GL_GEOMETRY_SHADER ? "geometry" : "fragment") + " shader did not compile: " + log.data());
  }
  return s;
}

GLuint link(std::initializer_list<GLuint> shaders, const char* const* feedback = nullptr, int feedback_count = 0) {
  GLuint p = glCreateProgram();
  for (GLuint s : shaders) glAttachShader(p, s);
  if (feedback) glTransformFeedbackVaryings(p, feedback_count, feedback, GL_SEPARATE_ATTRIBS);
  glLinkProgram(p);
  for (GLuint s : shaders) glDetachShader(p, s), glDeleteShader(s);
  GLint ok = 0;
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint n = 0;
    glGetProgramiv(p, GL_INFO_LOG_LENGTH, &n);
    std::vector<char> log(size_t(std::max(n, 1)));
    glGetProgramInfoLog(p, GLsizei(log.size()), nullptr, log.data());
    glDeleteProgram(p);
    throw Error(std::string("the GPU backend's program did not link: ") + log.data());
  }
  return p;
}

}  // namespace

GLuint build_program(const std::string& vertex, const std::string& geometry, const std::string& fragment) {
  if (geometry.empty()) return link({compile(GL_VERTEX_SHADER, vertex), compile(GL_FRAGMENT_SHADER, fragment)});
  return link({compile(GL_VERTEX_SHADER, vertex), compile(GL_GEOMETRY_SHADER, geometry),
               compile(GL_FRAGMENT_SHADER, fragment)});
}

GLuint build_mesh_program(bool affine, int primitive) {
  const std::string head = std::string(kVersion) + "#define INTERP " + (affine ? "noperspective" : "smooth") +
                           "\n#define PRIMITIVE " + std::to_string(primitive) + "\n" + kLightingGlsl + kColorGlsl;
  if (primitive == 3) return build_program(head + kMeshVertexInputs + kMeshVertexDirect, "", head + kMeshFragment);
  if (primitive == 1)  // edges by the CPU's line rule
    return build_program(head + kMeshVertexInputs + kMeshVertex, head + kLineQuadGlsl + kMeshGeometry,
                         head + kLineRuleGlsl + kMeshFragment);
  return build_program(head + kMeshVertexInputs + kMeshVertex, head + kMeshGeometry, head + kMeshFragment);
}

namespace {

// The Pbr kernels' vertex inputs (triangle/mesh_job.cpp's pbr_corner): eye normal and
// position, the material's uv set, the eye-space tangent and its handedness, the vertex
// colour (in the pipeline's space) and alpha.
const char* const kPbrVertex = R"(
layout(location = 4) in vec2 a_uv1;
layout(location = 5) in vec4 a_tangent;
layout(location = 6) in float a_alpha;
uniform bool u_uv1;
out P {
  INTERP vec3 eye;
  INTERP vec3 normal;
  INTERP vec2 uv;
  INTERP vec4 tangent;
  INTERP vec4 color;
} g;
void main() {
  gl_Position = u_mvp * vec4(a_position, 1.0);
  g.eye = (u_model_view * vec4(a_position, 1.0)).xyz;
  g.normal = normalize((u_normal_matrix * vec4(a_normal, 0.0)).xyz);
  g.uv = u_uv1 ? a_uv1 : a_uv;
  vec3 t = (u_model_view * vec4(a_tangent.xyz, 0.0)).xyz;
  g.tangent = vec4(dot(t, t) > 0.0 ? normalize(t) : t, a_tangent.w < 0.0 ? -1.0 : 1.0);
  g.color = vec4(to_pipeline(a_color), a_alpha);
}
)";

// raster/shade_pbr-inl.h's PbrShader and pbr_kernel: base colour (factor x vertex colour
// x texture), the normal through the normal map in the tangent frame (a back face of a
// double-sided material flips the whole frame), metallic and roughness (B and G),
// occlusion, emission, each texture through its own KHR_texture_transform; MASK
// discards under the cut-off, BLEND leaves the mixing to GL's blending (over, in the
// output's encoding).
const char* const kPbrFragment = R"(
in P {
  INTERP vec3 eye;
  INTERP vec3 normal;
  INTERP vec2 uv;
  INTERP vec4 tangent;
  INTERP vec4 color;
} g;
uniform bool u_two_sided;
uniform bool u_ortho;
uniform bool u_vertex_colors;
uniform bool u_tangents;
uniform vec4 u_base;
uniform vec4 u_pbr;  // metallic, roughness, normal scale, occlusion strength
uniform vec3 u_emissive;
uniform bool u_unlit;
uniform int u_alpha_mode;  // AlphaMode: 0 opaque, 1 mask, 2 blend
uniform float u_alpha_cutoff;
// The textures: base colour, metallic-roughness, normal, occlusion, emissive; each
// one's uv map as two rows (u' = a u + b v + c, v' = d u + e v + f).
uniform sampler2D u_base_map, u_mr_map, u_normal_map, u_occlusion_map, u_emissive_map;
uniform bool u_has_map[5];
uniform vec3 u_map_uv[10];
uniform uint u_object_id;
layout(location = 0) out vec4 o_color;
layout(location = 1) out uint o_id;

vec2 map_uv(int i) { return vec2(dot(u_map_uv[2 * i], vec3(g.uv, 1.0)), dot(u_map_uv[2 * i + 1], vec3(g.uv, 1.0))); }

void main() {
  vec3 c = u_base.rgb;
  float alpha = u_base.a;
  if (u_vertex_colors) c *= g.color.rgb, alpha *= g.color.a;
  if (u_has_map[0]) {
    vec4 t = texture(u_base_map, map_uv(0));
    c *= t.rgb, alpha *= t.a;
  }
  if (u_alpha_mode == 1 && alpha < u_alpha_cutoff) discard;
  if (!u_unlit) {
    bool back = u_two_sided && !gl_FrontFacing;
    vec3 n = normalize(g.normal);
    if (back) n = -n;
    if (u_tangents && u_has_map[2]) {
      vec3 t = texture(u_normal_map, map_uv(2)).rgb * 2.0 - 1.0;
      t.xy *= u_pbr.z;
      vec3 tan = back ? -g.tangent.xyz : g.tangent.xyz;
      tan = normalize(tan - n * dot(n, tan));
      float w = (g.tangent.w < 0.0) != back ? -1.0 : 1.0;
      vec3 bit = w * cross(n, tan);
      n = normalize(tan * t.x + bit * t.y + n * t.z);
    }
    float metallic = u_pbr.x, roughness = u_pbr.y;
    if (u_has_map[1]) {
      vec4 t = texture(u_mr_map, map_uv(1));
      metallic *= t.b, roughness *= t.g;
    }
    float ao = 1.0;
    if (u_has_map[3]) ao = u_pbr.w * (texture(u_occlusion_map, map_uv(3)).r - 1.0) + 1.0;
    vec3 view = u_ortho ? vec3(0.0, 0.0, 1.0) : normalize(-g.eye);
    c = pbr_light(n, view, g.eye, c, metallic, roughness, ao);
    vec3 e = u_emissive;
    if (u_has_map[4]) e *= texture(u_emissive_map, map_uv(4)).rgb;
    c += e;
  }
  o_color = vec4(finish(c), u_alpha_mode == 2 ? clamp(alpha, 0.0, 1.0) : 1.0);
  o_id = u_object_id;
}
)";

}  // namespace

GLuint build_pbr_program(bool affine) {
  const std::string head = std::string(kVersion) + "#define INTERP " + (affine ? "noperspective" : "smooth") + "\n" +
                           kLightingGlsl + kColorGlsl;
  return build_program(head + kMeshVertexInputs + kPbrVertex, "", head + kPbrGlsl + kPbrFragment);
}

// Pre-transformed primitives with OpenGL 1.x's per-fragment state (primitives.hpp, the
// CPU's raster/shade_fixed-inl.h): texture environment, fog, alpha test in that order;
// scissor, depth, blend and the colour mask are GL's own state. Clip-space y is negated
// as the mesh program's projection is (the image is drawn upside down).
const char* const kBatchVertex = R"(
layout(location = 0) in vec4 a_position;
layout(location = 1) in vec4 a_color;
layout(location = 2) in vec4 a_texcoord;
layout(location = 3) in float a_fog;
layout(location = 4) in vec4 a_clip0;  // user clip planes 0-3 (PrimitiveBatch::clip_distance)
layout(location = 5) in vec2 a_clip1;  // and 4-5; only the enabled ones clip
out float gl_ClipDistance[6];
uniform float u_point_size;
out vec4 v_color;
out vec3 v_texcoord;  // s, t, q: interpolated perspective-correct, divided per pixel
out float v_fog;
void main() {
  gl_Position = vec4(a_position.x, -a_position.y, a_position.z, a_position.w);
  gl_PointSize = u_point_size;
  v_color = a_color;
  v_texcoord = vec3(a_texcoord.x, a_texcoord.y, a_texcoord.w);
  v_fog = a_fog;
  gl_ClipDistance[0] = a_clip0.x, gl_ClipDistance[1] = a_clip0.y, gl_ClipDistance[2] = a_clip0.z;
  gl_ClipDistance[3] = a_clip0.w, gl_ClipDistance[4] = a_clip1.x, gl_ClipDistance[5] = a_clip1.y;
}
)";

// pGL's lines: the values of each end (cut where the segment was) for the fragment
// stage, and user clip planes cut here too.
const char* const kBatchLineGeometry = R"(
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;
in gl_PerVertex {
  vec4 gl_Position;
  float gl_PointSize;
  float gl_ClipDistance[6];
} gl_in[];
out float gl_ClipDistance[6];  // (the segment is clipped here: nothing left to clip)
in vec4 v_color[];
in vec3 v_texcoord[];
in float v_fog[];
uniform float u_line_width;
uniform int u_clip_planes;
flat out vec4 l_color0, l_color1;
flat out vec3 l_texcoord0, l_texcoord1;
flat out vec2 l_fog;

void line_vertex(float t0, float t1) {
  l_color0 = mix(v_color[0], v_color[1], t0), l_color1 = mix(v_color[0], v_color[1], t1);
  l_texcoord0 = mix(v_texcoord[0], v_texcoord[1], t0), l_texcoord1 = mix(v_texcoord[0], v_texcoord[1], t1);
  l_fog = vec2(mix(v_fog[0], v_fog[1], t0), mix(v_fog[0], v_fog[1], t1));
  for (int k = 0; k < 6; ++k) gl_ClipDistance[k] = 1.0;
}
)";

const char* const kBatchLineMain = R"(
void main() {
  float t0 = 0.0, t1 = 1.0;
  for (int k = 0; k < u_clip_planes; ++k)
    if (!cut(gl_in[0].gl_ClipDistance[k], gl_in[1].gl_ClipDistance[k], t0, t1)) return;
  emit_line(gl_in[0].gl_Position, gl_in[1].gl_Position, t0, t1, u_line_width);
}
)";

const char* const kBatchFragment = R"(
#ifdef LINES
flat in vec4 l_color0, l_color1;
flat in vec3 l_texcoord0, l_texcoord1;
flat in vec2 l_fog;
#else
in vec4 v_color;
in vec3 v_texcoord;
in float v_fog;
#endif
uniform bool u_textured;
uniform int u_format;  // TexFormat: 0 RGBA, 1 RGB, 2 L, 3 LA, 4 A, 5 I
uniform int u_env;     // TexEnvMode: 0 modulate, 1 replace, 2 decal, 3 blend, 4 add
uniform vec4 u_env_color;
uniform sampler2D u_texture;
uniform bool u_fog;
uniform int u_fog_mode;   // FogMode: 0 linear, 1 exp, 2 exp2
uniform vec3 u_fog_params;  // start, end, density
uniform vec4 u_fog_color;
uniform bool u_alpha_test;
uniform int u_alpha_func;  // CompareFunc
uniform float u_alpha_ref;
uniform bool u_offset;     // polygon offset, as the CPU applies it (PixelState)
uniform vec2 u_offset_params;  // factor, units
layout(location = 0) out vec4 o_color;
layout(location = 1) out uint o_id;

bool compare(int f, float a, float b) {
  if (f == 0) return false;
  if (f == 1) return a < b;
  if (f == 2) return a == b;
  if (f == 3) return a <= b;
  if (f == 4) return a > b;
  if (f == 5) return a != b;
  if (f == 6) return a >= b;
  return true;
}

// OpenGL 1.x's table of texture functions (GL 1.5 table 3.22) by base format.
vec4 environment(vec4 f, vec4 t) {
  bool has_color = u_format != 4, has_alpha = u_format == 0 || u_format == 3 || u_format == 4;
  if (u_format == 5) {  // intensity: I in every channel
    if (u_env == 0) return f * t.r;
    if (u_env == 1) return vec4(t.r);
    if (u_env == 3) return f * (1.0 - t.r) + u_env_color * t.r;
    if (u_env == 4) return clamp(f + vec4(t.r), 0.0, 1.0);
    return f;
  }
  vec3 c = f.rgb;
  float a = f.a;
  if (u_env == 0) {
    if (has_color) c = f.rgb * t.rgb;
    if (has_alpha) a = f.a * t.a;
  } else if (u_env == 1) {
    if (has_color) c = t.rgb;
    if (has_alpha) a = t.a;
  } else if (u_env == 2) {
    if (u_format == 0) c = mix(f.rgb, t.rgb, t.a);
    else if (u_format == 1) c = t.rgb;  // (undefined for the other formats: left as it is, as Mesa and the CPU)
  } else if (u_env == 3) {
    if (has_color) c = f.rgb * (1.0 - t.rgb) + u_env_color.rgb * t.rgb;
    if (has_alpha) a = f.a * t.a;
  } else if (u_env == 4) {
    if (has_color) c = clamp(f.rgb + t.rgb, 0.0, 1.0);
    if (has_alpha) a = f.a * t.a;
  }
  return vec4(c, a);
}

void main() {
#ifdef LINES
  // (The image is drawn upside down: GL's rows are the CPU's.)
  bool covered = line_covers(int(floor(gl_FragCoord.x)), int(floor(gl_FragCoord.y)));
  vec2 d = l_ends.zw - l_ends.xy;
  float t = line_t();
  float inv_w = mix(l_inv_w.x, l_inv_w.y, t);
  vec4 v_color = mix(l_color0 * l_inv_w.x, l_color1 * l_inv_w.y, t) / inv_w;
  vec3 v_texcoord = mix(l_texcoord0 * l_inv_w.x, l_texcoord1 * l_inv_w.y, t) / inv_w;
  float v_fog = mix(l_fog.x * l_inv_w.x, l_fog.y * l_inv_w.y, t) / inv_w;
  float depth = mix(l_shape.z, l_shape.w, t);
  float slope = max(abs((l_shape.w - l_shape.z) * d.x), abs((l_shape.w - l_shape.z) * d.y)) / dot(d, d);
#else
  bool covered = true;
  float depth = gl_FragCoord.z;
  float slope = max(abs(dFdx(gl_FragCoord.z)), abs(dFdy(gl_FragCoord.z)));
#endif
  vec4 c = clamp(v_color, 0.0, 1.0);
  if (u_textured) c = environment(c, texture(u_texture, v_texcoord.xy / v_texcoord.z));
  if (!covered) discard;
  if (u_fog) {
    float z = v_fog, f;
    if (u_fog_mode == 0) f = (u_fog_params.y - z) / (u_fog_params.y - u_fog_params.x);
    else if (u_fog_mode == 1) f = exp(-u_fog_params.z * z);
    else f = exp(-(u_fog_params.z * z) * (u_fog_params.z * z));
    f = clamp(f, 0.0, 1.0);
    c.rgb = f * c.rgb + (1.0 - f) * u_fog_color.rgb;
  }
  if (u_alpha_test && !compare(u_alpha_func, c.a, u_alpha_ref)) discard;
  gl_FragDepth = depth;
  if (u_offset) gl_FragDepth = clamp(depth + u_offset_params.x * slope + u_offset_params.y * exp2(-24.0), 0.0, 1.0);
  o_color = c;
  o_id = 0u;
}
)";

// A shadow map's depth pass (CpuBackend::render_shadows: the casters' depth, nothing else).
GLuint build_depth_program() {
  const std::string vs = std::string(kVersion) + R"(
layout(location = 0) in vec3 a_position;
uniform mat4 u_mvp;
void main() { gl_Position = u_mvp * vec4(a_position, 1.0); }
)";
  return build_program(vs, "", std::string(kVersion) + "void main() {}\n");
}

GLuint build_batch_program(bool lines) {
  const std::string head = std::string(kVersion) + (lines ? "#define LINES\n" : "");
  if (!lines) return build_program(head + kBatchVertex, "", head + kBatchFragment);
  return build_program(head + kBatchVertex, head + kBatchLineGeometry + kLineQuadGlsl + kBatchLineMain,
                       head + kLineRuleGlsl + kBatchFragment);
}

// One triangle covering the viewport (vertices 0-2, no buffers): the passes below shade
// every pixel of their target once.
const char* const kFullScreenVertex = R"(
void main() {
  vec2 p = vec2(float((gl_VertexID & 1) << 2), float((gl_VertexID & 2) << 1)) - 1.0;
  gl_Position = vec4(p, 0.0, 1.0);
}
)";

// The k x k box resolve (framebuffer/resolve.cpp's resolve_color_rows) as a pass over
// the sample texture: one triangle covering the w x h output, each pixel the rounded
// mean of its k x k samples' 8-bit values, in integers as the CPU computes it.
GLuint build_resolve_program() {
  const char* fs = R"(
uniform sampler2D u_samples;
uniform int u_k;
layout(location = 0) out vec4 o_color;
void main() {
  ivec2 at = ivec2(gl_FragCoord.xy) * u_k;
  uvec4 sum = uvec4(0u);
  for (int sy = 0; sy < u_k; ++sy)
    for (int sx = 0; sx < u_k; ++sx) sum += uvec4(round(texelFetch(u_samples, at + ivec2(sx, sy), 0) * 255.0));
  uint n = uint(u_k * u_k);
  o_color = vec4((sum + uvec4(n / 2u)) / uvec4(n)) / 255.0;
}
)";
  return build_program(std::string(kVersion) + kFullScreenVertex, "", std::string(kVersion) + fs);
}

GLuint build_overlay_program() {
  const char* fs = R"(
uniform sampler2D u_layer;
uniform vec4 u_viewport;
uniform ivec4 u_box;  // this frame's texels: [x0, x1) x [y0, y1), top row 0
layout(location = 0) out vec4 o_color;
void main() {
  ivec2 size = textureSize(u_layer, 0);
  vec2 f = (gl_FragCoord.xy - u_viewport.xy) / u_viewport.zw;  // 0..1 from the bottom left
  ivec2 at = clamp(ivec2(floor(vec2(f.x, 1.0 - f.y) * vec2(size))), ivec2(0), size - 1);
  if (any(lessThan(at, u_box.xy)) || any(greaterThanEqual(at, u_box.zw))) discard;
  o_color = texelFetch(u_layer, at, 0);
}
)";
  return build_program(std::string(kVersion) + kFullScreenVertex, "", std::string(kVersion) + fs);
}

GLuint build_lighting_test_program() {
  const std::string vs = std::string(kVersion) + kLightingGlsl + R"(
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
out vec3 o_diffuse;
out vec3 o_specular;
void main() {
  Terms t = light(a_normal, a_position);
  o_diffuse = t.diffuse, o_specular = t.specular;
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
)";
  static const char* const outputs[] = {"o_diffuse", "o_specular"};
  return link({compile(GL_VERTEX_SHADER, vs)}, outputs, 2);
}

GLuint build_pbr_test_program() {
  const std::string vs = std::string(kVersion) + kLightingGlsl + kPbrGlsl + R"(
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_view;
layout(location = 3) in vec3 a_base;
layout(location = 4) in vec3 a_material;  // metallic, roughness, occlusion
out vec3 o_color;
void main() {
  o_color = pbr_light(a_normal, a_view, a_position, a_base, a_material.x, a_material.y, a_material.z);
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
)";
  static const char* const outputs[] = {"o_color"};
  return link({compile(GL_VERTEX_SHADER, vs)}, outputs, 1);
}

}  // namespace velocity::gpu
