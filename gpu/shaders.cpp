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
    add_light(t, n, u_directional_to_light[i], u_directional_color[i], to_eye);
  for (int i = 0; i < u_point_count; ++i) {
    vec3 to_light;
    float att = punctual(i, p, n, to_light);
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
    c += pbr_add_light(n, view, u_directional_to_light[i], u_directional_color[i], cdiff, f0, ms, a2, nv, nv_term);
  for (int i = 0; i < u_point_count; ++i) {
    vec3 to_light;
    float att = punctual(i, p, n, to_light);
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
layout(line_strip, max_vertices = 6) out;
#else
layout(points, max_vertices = 3) out;
#endif
uniform bool u_cull;
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
  if (u_cull && det >= 0.0) return;
#endif
#if PRIMITIVE == 1
  const int corners[6] = int[6](0, 1, 1, 2, 2, 0);
  for (int k = 0; k < 6; ++k) {
    int i = corners[k];
#else
  for (int i = 0; i < 3; ++i) {
#endif
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
    EmitVertex();
#if PRIMITIVE == 1
    if (k % 2 == 1) EndPrimitive();
#elif PRIMITIVE == 2
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
}
)";

const char* const kBatchFragment = R"(
in vec4 v_color;
in vec3 v_texcoord;
in float v_fog;
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
  vec4 c = clamp(v_color, 0.0, 1.0);
  if (u_textured) c = environment(c, texture(u_texture, v_texcoord.xy / v_texcoord.z));
  if (u_fog) {
    float z = v_fog, f;
    if (u_fog_mode == 0) f = (u_fog_params.y - z) / (u_fog_params.y - u_fog_params.x);
    else if (u_fog_mode == 1) f = exp(-u_fog_params.z * z);
    else f = exp(-(u_fog_params.z * z) * (u_fog_params.z * z));
    f = clamp(f, 0.0, 1.0);
    c.rgb = f * c.rgb + (1.0 - f) * u_fog_color.rgb;
  }
  if (u_alpha_test && !compare(u_alpha_func, c.a, u_alpha_ref)) discard;
  gl_FragDepth = gl_FragCoord.z;
  if (u_offset) {
    float slope = max(abs(dFdx(gl_FragCoord.z)), abs(dFdy(gl_FragCoord.z)));
    gl_FragDepth = clamp(gl_FragCoord.z + u_offset_params.x * slope + u_offset_params.y * exp2(-24.0), 0.0, 1.0);
  }
  o_color = c;
  o_id = 0u;
}
)";

GLuint build_batch_program() {
  return build_program(std::string(kVersion) + kBatchVertex, "", std::string(kVersion) + kBatchFragment);
}

// The k x k box resolve (framebuffer/resolve.cpp's resolve_color_rows) as a pass over
// the sample texture: one triangle covering the w x h output, each pixel the rounded
// mean of its k x k samples' 8-bit values, in integers as the CPU computes it.
GLuint build_resolve_program() {
  const char* vs = R"(
void main() {
  vec2 p = vec2(float((gl_VertexID & 1) << 2), float((gl_VertexID & 2) << 1)) - 1.0;
  gl_Position = vec4(p, 0.0, 1.0);
}
)";
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
  return build_program(std::string(kVersion) + vs, "", std::string(kVersion) + fs);
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
