// Reference renderer on OSMesa/llvmpipe. The arithmetic in the mesh builders below is
// kept in float and in a fixed order on purpose: the images must match glref's bit for
// bit, and reordering a sum or turning a division into a multiplication by the
// reciprocal is enough to move a normal by an ulp and a pixel by one level.
#include "reference.hpp"

#define GL_GLEXT_PROTOTYPES 1  // libOSMesa exports the GL 2.0 shader entry points
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stb/stb_image.h>
#include <tiny_obj_loader.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <map>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace vref {
namespace {

using Vec3 = std::array<float, 3>;

Vec3 vertex(const Mesh& m, uint32_t i) { return {m.pos[3 * i], m.pos[3 * i + 1], m.pos[3 * i + 2]}; }

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

float length(const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

// Zero-length vectors (degenerate triangles) stay zero rather than becoming NaN.
Vec3 normalised(const Vec3& v) {
  const float l = length(v);
  if (l > 0) return {v[0] / l, v[1] / l, v[2] / l};
  return {0.f, 0.f, 0.f};
}

// Unnormalised face normal of triangle t: (v1-v0) x (v2-v0).
Vec3 face_cross(const Mesh& m, size_t t) {
  const Vec3 a = vertex(m, m.idx[3 * t]), b = vertex(m, m.idx[3 * t + 1]), c = vertex(m, m.idx[3 * t + 2]);
  return cross(sub(b, a), sub(c, a));
}

void append(std::vector<float>& v, std::initializer_list<float> xs) { v.insert(v.end(), xs); }

// For each vertex, the first vertex with exactly the same position. std::array's
// operator< compares with float <, so -0 and +0 weld, as a tuple sort would.
std::vector<uint32_t> weld_by_position(const Mesh& m) {
  std::map<Vec3, uint32_t> first;
  std::vector<uint32_t> rep(m.vertices());
  for (uint32_t i = 0; i < rep.size(); ++i) rep[i] = first.try_emplace(vertex(m, i), i).first->second;
  return rep;
}

// Smooth normals: face normals (area weighted, being unnormalised cross products)
// summed in triangle order over every corner that shares a position.
void smooth_normals(Mesh& m) {
  const std::vector<uint32_t> rep = weld_by_position(m);
  std::vector<Vec3> sum(m.vertices(), Vec3{0.f, 0.f, 0.f});
  for (size_t t = 0; t < m.triangles(); ++t) {
    const Vec3 n = face_cross(m, t);
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j) sum[rep[m.idx[3 * t + k]]][j] += n[j];
  }
  m.nrm.clear();
  m.nrm.reserve(m.pos.size());
  for (uint32_t i = 0; i < m.vertices(); ++i) {
    const Vec3 n = normalised(sum[rep[i]]);
    m.nrm.insert(m.nrm.end(), n.begin(), n.end());
  }
}

// Parses all of `s` as a decimal int; nullopt on anything else.
std::optional<int> parse_int(std::string_view s) {
  int value = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return value;
}

// The mesh's axis-aligned bounding box (lo above hi when it has no vertices).
void bounding_box(const Mesh& m, Vec3& lo, Vec3& hi) {
  lo = {1e30f, 1e30f, 1e30f}, hi = {-1e30f, -1e30f, -1e30f};
  for (uint32_t i = 0; i < m.vertices(); ++i)
    for (int j = 0; j < 3; ++j) {
      lo[j] = std::min(lo[j], m.pos[3 * i + j]);
      hi[j] = std::max(hi[j], m.pos[3 * i + j]);
    }
}

}  // namespace

// ---------------------------------------------------------------------------------
// Meshes

Mesh make_sphere(int segs) {
  if (segs < 3 || segs > 16384) throw std::invalid_argument("sphere segments must be in [3, 16384], got " + std::to_string(segs));
  const int rings = segs / 2;
  const float pi = std::numbers::pi_v<float>;
  Mesh m;
  for (int r = 0; r <= rings; ++r) {
    const float v = float(r) / float(rings), theta = v * pi;  // theta from the north pole
    for (int s = 0; s <= segs; ++s) {
      // The seam column s == segs duplicates s == 0 with u = 1, for texturing.
      const float u = float(s) / float(segs), phi = u * 2.f * pi;
      const float x = std::sin(theta) * std::cos(phi), y = std::cos(theta), z = -std::sin(theta) * std::sin(phi);
      append(m.pos, {x, y, z});
      append(m.nrm, {x, y, z});
      append(m.uv, {u, 1.f - v});
    }
  }
  const auto row = uint32_t(segs + 1);
  for (uint32_t r = 0; r < uint32_t(rings); ++r)
    for (uint32_t s = 0; s < uint32_t(segs); ++s) {
      const uint32_t a = r * row + s, b = a + row;  // b is a's neighbour one ring south
      m.idx.insert(m.idx.end(), {a, b, a + 1, a + 1, b, b + 1});
    }
  return m;
}

Mesh load_obj(const std::string& path) {
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path)) {
    std::string why = reader.Error();
    while (!why.empty() && std::isspace(static_cast<unsigned char>(why.back()))) why.pop_back();  // ends in '\n'
    if (why.empty()) why = "parse failed";
    throw std::runtime_error("cannot load OBJ '" + path + "': " + why);
  }
  const tinyobj::attrib_t& at = reader.GetAttrib();
  Mesh m;
  // One vertex per face corner; smooth_normals() welds them back by position.
  for (const tinyobj::shape_t& shape : reader.GetShapes())
    for (const tinyobj::index_t& ix : shape.mesh.indices) {
      const auto p = size_t(ix.vertex_index);
      append(m.pos, {at.vertices[3 * p], at.vertices[3 * p + 1], at.vertices[3 * p + 2]});
      if (ix.texcoord_index >= 0) {
        const auto t = size_t(ix.texcoord_index);
        append(m.uv, {at.texcoords[2 * t], at.texcoords[2 * t + 1]});
      } else {
        append(m.uv, {0.f, 0.f});
      }
      m.idx.push_back(uint32_t(m.idx.size()));
    }
  if (m.triangles() == 0) throw std::runtime_error("OBJ '" + path + "' has no triangles");
  smooth_normals(m);
  return m;
}

Mesh load_mesh(std::string_view spec) {
  constexpr std::string_view prefix = "sphere:";
  if (!spec.starts_with(prefix)) return load_obj(std::string(spec));
  const std::optional<int> segs = parse_int(spec.substr(prefix.size()));
  if (!segs) throw std::invalid_argument("bad mesh spec '" + std::string(spec) + "' (expected sphere:SEGS or FILE.obj)");
  return make_sphere(*segs);
}

void normalise(Mesh& m) {
  Vec3 lo, hi;
  bounding_box(m, lo, hi);
  const Vec3 centre{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
  float radius = 0;
  for (uint32_t i = 0; i < m.vertices(); ++i) radius = std::max(radius, length(sub(vertex(m, i), centre)));
  if (!(radius > 0)) return;  // empty or a single point: nothing sensible to scale
  for (uint32_t i = 0; i < m.vertices(); ++i)
    for (int j = 0; j < 3; ++j) m.pos[3 * i + j] = (m.pos[3 * i + j] - centre[j]) / radius;
}

Mesh face_normals(const Mesh& in) {
  Mesh m;
  m.pos.reserve(9 * in.triangles());
  m.nrm.reserve(9 * in.triangles());
  m.uv.reserve(6 * in.triangles());
  m.idx.reserve(in.idx.size());
  for (size_t t = 0; t < in.triangles(); ++t) {
    const Vec3 n = normalised(face_cross(in, t));
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = in.idx[3 * t + k];
      append(m.pos, {in.pos[3 * v], in.pos[3 * v + 1], in.pos[3 * v + 2]});
      append(m.uv, {in.uv[2 * v], in.uv[2 * v + 1]});
      m.nrm.insert(m.nrm.end(), n.begin(), n.end());
      m.idx.push_back(uint32_t(m.idx.size()));
    }
  }
  return m;
}

// ---------------------------------------------------------------------------------
// Shading modes and images

namespace {
constexpr std::array<std::pair<Shade, std::string_view>, 8> kShadeNames{{
    {Shade::Flat, "flat"},
    {Shade::Gouraud, "gouraud"},
    {Shade::Tex, "tex"},
    {Shade::Phong, "phong"},
    {Shade::Env, "env"},
    {Shade::Wire, "wire"},
    {Shade::Pbr, "pbr"},
    {Shade::PbrTex, "pbrtex"},
}};
}  // namespace

std::optional<Shade> parse_shade(std::string_view name) {
  for (const auto& [shade, n] : kShadeNames)
    if (n == name) return shade;
  return std::nullopt;
}

bool textured(Shade shade) { return shade == Shade::Tex || shade == Shade::Env || shade == Shade::PbrTex; }

std::string_view to_string(Shade shade) {
  for (const auto& [s, name] : kShadeNames)
    if (s == shade) return name;
  return "?";
}

Image checkerboard() {
  constexpr int kSize = 256, kSquare = 32;
  Image img{kSize, kSize, std::vector<uint8_t>(size_t(kSize) * kSize * 4)};
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const bool light = ((x / kSquare) ^ (y / kSquare)) & 1;
      uint8_t* px = &img.rgba[(size_t(y) * kSize + x) * 4];
      px[0] = light ? 230 : 40;
      px[1] = light ? 200 : 60;
      px[2] = light ? 80 : 160;
      px[3] = 255;
    }
  return img;
}

Image load_image(const std::string& path) {
  int w = 0, h = 0, channels = 0;
  std::unique_ptr<stbi_uc, void (*)(void*)> data(stbi_load(path.c_str(), &w, &h, &channels, 4), stbi_image_free);
  if (!data) {
    const char* why = stbi_failure_reason();
    throw std::runtime_error("cannot load image '" + path + "': " + (why ? why : "unknown error"));
  }
  Image img{w, h, {}};
  img.rgba.assign(data.get(), data.get() + size_t(w) * h * 4);
  return img;
}

// ---------------------------------------------------------------------------------
// Renderer

namespace {

// Per-pixel lighting for phong and env: the fixed-function formula evaluated per
// fragment, plus a white Phong (reflection-vector) specular. GLSL 1.20 so that
// it can read the fixed-function matrices. Env (with ENV defined) swaps the material
// colour for a sphere-map lookup by the eye-space normal.
constexpr const char* kVertexShader = R"(
varying vec3 v_normal;   // eye space
varying vec3 v_position; // eye space
varying vec2 v_uv;
void main() {
  v_normal = gl_NormalMatrix * gl_Normal;
  v_position = vec3(gl_ModelViewMatrix * gl_Vertex);
  v_uv = gl_MultiTexCoord0.xy;
  gl_Position = ftransform();
}
)";

// The light's visibility at eye-space point p (normal n, towards the light l): 0 facing
// away from it; with SHADOWS, the depth-compare sampler's bilinear (percentage-closer)
// filter of the map at p moved two texels along n and one towards the light, the
// engine's bias (its shading/shadow.hpp); else 1.
constexpr const char* kVisibility = R"(
#ifdef SHADOWS
uniform sampler2DShadow u_shadow;
uniform mat4 u_eye_to_shadow;  // eye space to the map's texture coordinates and depth, all in [0, 1]
uniform float u_texel;         // a texel's side in eye-space units
float visibility(vec3 p, vec3 n, vec3 l) {
  if (dot(n, l) <= 0.0) return 0.0;
  vec4 s = u_eye_to_shadow * vec4(p + n * (2.0 * u_texel) + l * u_texel, 1.0);
  return shadow2D(u_shadow, s.xyz).r;
}
#else
float visibility(vec3 p, vec3 n, vec3 l) { return 1.0; }
#endif
)";

constexpr const char* kFragmentShader = R"(
uniform vec3 u_light;    // direction towards the light, eye space, unit length
uniform sampler2D u_texture;
varying vec3 v_normal;
varying vec3 v_position;
void main() {
  vec3 n = normalize(v_normal);
  vec3 to_eye = normalize(-v_position);
  float diffuse = max(dot(n, u_light), 0.0);
  float specular = pow(max(dot(reflect(-u_light, n), to_eye), 0.0), 32.0);
#ifdef ENV
  vec3 base = texture2D(u_texture, vec2(0.5 + 0.5 * n.x, 0.5 + 0.5 * n.y)).rgb;
#else
  vec3 base = vec3(0.8, 0.7, 0.6);
#endif
  float lit = visibility(v_position, n, u_light);  // 1 without SHADOWS: the products are exact
  gl_FragColor = vec4(base * (0.2 + 0.8 * diffuse * lit) + vec3(0.5) * specular * lit, 1.0);
}
)";

// glTF 2.0's metallic-roughness BRDF (its Appendix B: Lambert diffuse, GGX / Trowbridge-
// Reitz specular, Smith's height-correlated visibility, Schlick's Fresnel; the dielectric
// and metal lobes mixed by metallic), for the engine's bench material: base colour
// u_base (linear; with TEXTURE times the sRGB texture, which GL decodes), metallic 0.3,
// roughness 0.5; ambient radiance 0.2 (Lambert of a uniform light: c_diff times it) and
// the directional light's 0.8; the sum sRGB-encoded. The engine adds Turquin's
// multiple-scattering factor to the specular lobe (1.00-1.06 here); this does not.
constexpr const char* kPbrFragmentShader = R"(
uniform vec3 u_light;
uniform vec3 u_base;
uniform sampler2D u_texture;
varying vec3 v_normal;
varying vec3 v_position;
varying vec2 v_uv;
const float kPi = 3.14159265;
vec3 encode(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}
void main() {
  vec3 n = normalize(v_normal), v = normalize(-v_position), l = u_light;
  vec3 base = u_base;
#ifdef TEXTURE
  base *= texture2D(u_texture, v_uv).rgb;
#endif
  const float metallic = 0.3, a = 0.25;  // a = roughness^2
  float a2 = a * a;
  vec3 cdiff = base * (1.0 - metallic), f0 = mix(vec3(0.04), base, metallic);
  float nv = max(dot(n, v), 1e-4);
  vec3 colour = 0.2 * cdiff;
  float nl = dot(n, l);
  if (nl > 0.0) {
    vec3 h = normalize(l + v);
    float nh = clamp(dot(n, h), 0.0, 1.0), q5 = pow(1.0 - clamp(dot(v, h), 0.0, 1.0), 5.0);
    vec3 f = f0 + (1.0 - f0) * q5;
    float dn = nh * nh * (a2 - 1.0) + 1.0;
    float d = a2 / (kPi * dn * dn);
    float vis = 0.5 / (nl * sqrt(nv * nv * (1.0 - a2) + a2) + nv * sqrt(nl * nl * (1.0 - a2) + a2));
    vec3 brdf = (1.0 - (0.04 + 0.96 * q5)) * cdiff / kPi + f * d * vis;
    colour += brdf * 0.8 * nl * visibility(v_position, n, l);
  }
  gl_FragColor = vec4(encode(colour), 1.0);
}
)";

GLuint compile_shader(GLenum type, const std::string& source) {
  const GLuint shader = glCreateShader(type);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    std::array<char, 4096> log{};
    glGetShaderInfoLog(shader, GLsizei(log.size()), nullptr, log.data());
    glDeleteShader(shader);
    throw std::runtime_error(std::string("shader compile failed: ") + log.data());
  }
  return shader;
}

GLuint build_program(Shade shade, bool shadows) {
  std::string header = "#version 120\n";
  if (shade == Shade::Env) header += "#define ENV 1\n";
  if (shade == Shade::PbrTex) header += "#define TEXTURE 1\n";
  if (shadows) header += "#define SHADOWS 1\n";
  const bool pbr = shade == Shade::Pbr || shade == Shade::PbrTex;
  const GLuint vs = compile_shader(GL_VERTEX_SHADER, header + kVertexShader);
  const GLuint fs = compile_shader(GL_FRAGMENT_SHADER, header + kVisibility + (pbr ? kPbrFragmentShader : kFragmentShader));
  const GLuint program = glCreateProgram();
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  glDeleteShader(vs);  // flagged; freed with the program
  glDeleteShader(fs);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    std::array<char, 4096> log{};
    glGetProgramInfoLog(program, GLsizei(log.size()), nullptr, log.data());
    glDeleteProgram(program);
    throw std::runtime_error(std::string("shader link failed: ") + log.data());
  }
  return program;
}

// The light direction, normalised in float as the convention's numbers are.
Vec3 light_direction() { return normalised({0.3f, 0.5f, 1.f}); }

float dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// 4x4 matrices column by column, as GL takes them.
using Mat4 = std::array<float, 16>;

Mat4 multiply(const Mat4& a, const Mat4& b) {
  Mat4 c{};
  for (int col = 0; col < 4; ++col)
    for (int row = 0; row < 4; ++row)
      for (int k = 0; k < 4; ++k) c[col * 4 + row] += a[k * 4 + row] * b[col * 4 + k];
  return c;
}

// gluLookAt's matrix.
Mat4 look_at(const Vec3& eye, const Vec3& centre, const Vec3& up) {
  const Vec3 f = normalised(sub(centre, eye)), s = normalised(cross(f, up)), u = cross(s, f);
  return {s[0], u[0], -f[0], 0, s[1], u[1], -f[1], 0, s[2], u[2], -f[2], 0, -dot(s, eye), -dot(u, eye), dot(f, eye), 1};
}

// glOrtho's matrix.
Mat4 ortho(float l, float r, float b, float t, float n, float f) {
  return {2 / (r - l), 0, 0, 0, 0, 2 / (t - b), 0, 0, 0, 0, -2 / (f - n), 0, -(r + l) / (r - l), -(t + b) / (t - b), -(f + n) / (f - n), 1};
}

// The shadow map's view, as the engine fits a directional light's: an orthographic box
// around the casters' bounding sphere (that of the mesh's bounding box), seen from two
// radii away towards the light; eye space to the light's view, and its projection.
struct ShadowView {
  Mat4 view, projection;
  float radius;
};

ShadowView shadow_view(const Mesh& m) {
  Vec3 lo, hi;
  bounding_box(m, lo, hi);
  const float r = 0.5f * length(sub(hi, lo));
  // The box's centre, turned about +Y with the mesh: normalise() put it at the origin.
  const Vec3 centre{0, 0, -3}, l = light_direction();
  const Vec3 at{centre[0] + 2 * r * l[0], centre[1] + 2 * r * l[1], centre[2] + 2 * r * l[2]};
  const Vec3 up = std::fabs(l[1]) > 0.99f ? Vec3{0, 0, 1} : Vec3{0, 1, 0};
  return {look_at(at, centre, up), ortho(-r, r, -r, r, 0.5f * r, 3.5f * r), r};
}

// sRGB-encoded to linear (IEC 61966-2-1).
float srgb_to_linear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

Mesh prepare_mesh(const Scene& scene) {
  Mesh m = load_mesh(scene.mesh);
  normalise(m);
  if (scene.shade == Shade::Flat) m = face_normals(m);
  return m;
}

void validate(const Scene& scene) {
  // llvmpipe's largest render target is 16384 square; fail early with a clear message.
  if (scene.width < 1 || scene.height < 1 || scene.width > 16384 || scene.height > 16384)
    throw std::invalid_argument("bad image size " + std::to_string(scene.width) + "x" + std::to_string(scene.height));
  if (scene.copies < 1) throw std::invalid_argument("copies must be at least 1, got " + std::to_string(scene.copies));
  if (scene.shadows) {
    if (scene.shade != Shade::Phong && scene.shade != Shade::Env && scene.shade != Shade::Pbr && scene.shade != Shade::PbrTex)
      throw std::invalid_argument("shadows need a programmable shade (phong, env, pbr or pbrtex), not " +
                                  std::string(to_string(scene.shade)));
    if (scene.copies != 1) throw std::invalid_argument("shadows are drawn for one copy of the mesh only");
    if (scene.shadow_map_size < 16 || scene.shadow_map_size > 8192)
      throw std::invalid_argument("shadow map size " + std::to_string(scene.shadow_map_size) + " is out of range (16..8192)");
  }
}

// Destroys an OSMesa context, unbinding it first if it is current so that a later
// context allocated at the same address is not mistaken for already bound.
struct ContextDeleter {
  void operator()(osmesa_context* ctx) const {
    if (OSMesaGetCurrentContext() == ctx) OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(ctx);  // frees its textures and programs too
  }
};
}  // namespace

struct Renderer::State {
  Scene scene;
  Mesh mesh;
  int grid = 1;                    // copies are laid out grid x grid
  std::vector<uint8_t> colour;     // OSMesa's colour buffer, bottom row first
  std::unique_ptr<osmesa_context, ContextDeleter> context;
  GLuint texture = 0, program = 0;
  GLuint shadow_texture = 0, shadow_framebuffer = 0;
  ShadowView light{};

  explicit State(const Scene& s);

  void make_current();
  void setup_camera() const;
  void setup_texture();
  void setup_fixed_function() const;
  void setup_program();
  void setup_wire() const;
  void setup_shadows();
  void bind_arrays() const;
  void draw_meshes(int frame, int frames) const;
  void draw(int frame, int frames) const;
};

Renderer::State::State(const Scene& s) : scene(s) {
  validate(scene);
  mesh = prepare_mesh(scene);
  grid = int(std::ceil(std::sqrt(double(scene.copies))));
  colour.resize(size_t(scene.width) * scene.height * 4);

  context.reset(OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr));
  if (!context) throw std::runtime_error("OSMesaCreateContextExt failed");
  make_current();

  setup_camera();
  if (textured(scene.shade)) setup_texture();
  switch (scene.shade) {
    case Shade::Flat:
    case Shade::Gouraud:
    case Shade::Tex: setup_fixed_function(); break;
    case Shade::Phong:
    case Shade::Env:
    case Shade::Pbr:
    case Shade::PbrTex: setup_program(); break;
    case Shade::Wire: setup_wire(); break;
  }
  if (scene.shadows) setup_shadows();
  bind_arrays();
}

// A context only renders on the thread it is current on; with several Renderers
// alive the last one created holds the thread, so each draw re-binds its own.
void Renderer::State::make_current() {
  if (OSMesaGetCurrentContext() == context.get()) return;
  if (!OSMesaMakeCurrent(context.get(), colour.data(), GL_UNSIGNED_BYTE, scene.width, scene.height))
    throw std::runtime_error("OSMesaMakeCurrent failed");
}

void Renderer::State::setup_camera() const {
  const double w = scene.width, h = scene.height;
  glViewport(0, 0, scene.width, scene.height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  const double top = 0.1 * std::tan(22.5 * std::numbers::pi / 180.0);  // near * tan(fov / 2)
  glFrustum(-top * w / h, top * w / h, -top, top, 0.1, 100.0);
  glMatrixMode(GL_MODELVIEW);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glEnable(GL_CULL_FACE);  // default: back faces of CCW-front triangles
  glClearColor(0.1f, 0.1f, 0.15f, 1.f);
}

// Uploads the texture (rows in memory order, so image row 0 is t = 0, as glref does)
// with a generated mip chain for trilinear filtering.
void Renderer::State::setup_texture() {
  const Image img = scene.texture.empty() ? checkerboard() : scene.texture;
  if (img.rgba.size() != size_t(img.width) * img.height * 4 || img.width < 1 || img.height < 1)
    throw std::invalid_argument("texture size does not match its pixel data");
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  // Images are stored top row first; OpenGL's t = 0 is the first row it is given, and the
  // convention's t = 0 is the image's bottom row (OBJ's and 3D Studio's v; the sphere
  // map's too, whose top row shows at Ny = 1): the rows go up bottom first, as in
  // ../shared/tools/glref.
  const size_t row = size_t(img.width) * 4;
  std::vector<uint8_t> upright(img.rgba.size());
  for (int y = 0; y < img.height; ++y)
    std::memcpy(&upright[size_t(y) * row], &img.rgba[size_t(img.height - 1 - y) * row], row);
  // PBR's base colour texture is sRGB-encoded (glTF's, and the engine's for every colour
  // texture in a linear frame): GL decodes it before filtering.
  const GLint format = scene.shade == Shade::PbrTex ? GL_SRGB8_ALPHA8 : GL_RGBA;
  glTexImage2D(GL_TEXTURE_2D, 0, format, img.width, img.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, upright.data());
  scene.texture = Image{};  // GL holds its own copy now
}

// Flat, gouraud and tex: GL 1.x lighting reproduces material * (0.2 + 0.8 * N.L)
// exactly once the global ambient (0.2 by default) is switched off and the light
// carries the 0.2 ambient term instead.
void Renderer::State::setup_fixed_function() const {
  const GLfloat none[4] = {0, 0, 0, 1}, ambient[4] = {0.2f, 0.2f, 0.2f, 1}, diffuse[4] = {0.8f, 0.8f, 0.8f, 1};
  const GLfloat material[4] = {0.8f, 0.7f, 0.6f, 1}, white[4] = {1, 1, 1, 1};
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, none);
  glLightfv(GL_LIGHT0, GL_AMBIENT, ambient);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
  glShadeModel(scene.shade == Shade::Flat ? GL_FLAT : GL_SMOOTH);
  if (scene.shade == Shade::Tex) {
    // Lighting on a white material, then the texture multiplies it.
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, white);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  } else {
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, material);
  }
}

void Renderer::State::setup_program() {
  program = build_program(scene.shade, scene.shadows);
  glUseProgram(program);
  const Vec3 l = light_direction();
  glUniform3f(glGetUniformLocation(program, "u_light"), l[0], l[1], l[2]);
  if (const GLint loc = glGetUniformLocation(program, "u_texture"); loc >= 0) glUniform1i(loc, 0);
  // PBR's base colour: the material's (0.8, 0.7, 0.6), sRGB-encoded as the engine's
  // material colours are; white under a texture, as the engine's bench draws pbrtex.
  if (const GLint loc = glGetUniformLocation(program, "u_base"); loc >= 0) {
    if (scene.shade == Shade::PbrTex)
      glUniform3f(loc, 1.0f, 1.0f, 1.0f);
    else
      glUniform3f(loc, srgb_to_linear(0.8f), srgb_to_linear(0.7f), srgb_to_linear(0.6f));
  }
}

// The depth texture (16 bits, as the engine's codes) the light's view is drawn into,
// read through texture unit 1 with depth comparison (LEQUAL: lit where the point is no
// farther than the caster) and linear filtering, which GL defines as the comparisons'
// bilinear blend; and the matrix from eye space to its texture coordinates.
void Renderer::State::setup_shadows() {
  const int size = scene.shadow_map_size;
  light = shadow_view(mesh);
  glGenTextures(1, &shadow_texture);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, shadow_texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT16, size, size, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glActiveTexture(GL_TEXTURE0);
  glGenFramebuffers(1, &shadow_framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, shadow_framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, shadow_texture, 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) throw std::runtime_error("the shadow map's framebuffer is incomplete");
  const Mat4 bias{0.5f, 0, 0, 0, 0, 0.5f, 0, 0, 0, 0, 0.5f, 0, 0.5f, 0.5f, 0.5f, 1};
  const Mat4 eye_to_shadow = multiply(bias, multiply(light.projection, light.view));
  glUniformMatrix4fv(glGetUniformLocation(program, "u_eye_to_shadow"), 1, GL_FALSE, eye_to_shadow.data());
  glUniform1f(glGetUniformLocation(program, "u_texel"), 2 * light.radius / float(size));
  glUniform1i(glGetUniformLocation(program, "u_shadow"), 1);
}

void Renderer::State::setup_wire() const {
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glDisable(GL_CULL_FACE);  // the far side's edges show through, as in any wireframe
  glColor3f(0.9f, 0.9f, 0.9f);
}

// Client-side arrays, as glref uses, so that the timings are comparable with its.
void Renderer::State::bind_arrays() const {
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, mesh.pos.data());
  glNormalPointer(GL_FLOAT, 0, mesh.nrm.data());
  glTexCoordPointer(2, GL_FLOAT, 0, mesh.uv.data());
}

// The mesh (its copies) from the modelview matrix's eye space.
void Renderer::State::draw_meshes(int frame, int frames) const {
  glTranslatef(0, 0, -3);  // the camera at (0, 0, 3)
  const float angle = 360.f * float(frame) / float(frames);
  for (int c = 0; c < scene.copies; ++c) {
    glPushMatrix();
    if (scene.copies > 1) {
      // Cell c of the grid covering [-1, 1]^2, filled row by row from the bottom left.
      const float cell = 2.0f / float(grid);
      glTranslatef(-1 + cell * (float(c % grid) + 0.5f), -1 + cell * (float(c / grid) + 0.5f), 0);
      glScalef(cell * 0.5f, cell * 0.5f, cell * 0.5f);
    }
    glRotatef(angle, 0, 1, 0);
    glDrawElements(GL_TRIANGLES, GLsizei(mesh.idx.size()), GL_UNSIGNED_INT, mesh.idx.data());
    glPopMatrix();
  }
}

void Renderer::State::draw(int frame, int frames) const {
  if (scene.shadows) {
    // The light's view, depth only: no program, no colour.
    glBindFramebuffer(GL_FRAMEBUFFER, shadow_framebuffer);
    glViewport(0, 0, scene.shadow_map_size, scene.shadow_map_size);
    glClear(GL_DEPTH_BUFFER_BIT);
    glUseProgram(0);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadMatrixf(light.projection.data());
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixf(light.view.data());
    draw_meshes(frame, frames);
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, scene.width, scene.height);
    glUseProgram(program);
  }
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glLoadIdentity();
  // A w = 0 position set under the identity is a direction fixed in eye space.
  const Vec3 l = light_direction();
  const GLfloat light_position[4] = {l[0], l[1], l[2], 0.f};
  glLightfv(GL_LIGHT0, GL_POSITION, light_position);
  draw_meshes(frame, frames);
  glFinish();
}

Renderer::Renderer(const Scene& scene) : state_(std::make_unique<State>(scene)) {}
Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

void Renderer::draw_frame(int frame, int frames) {
  if (frames < 1) throw std::invalid_argument("frames must be at least 1");
  state_->make_current();
  state_->draw(frame, frames);
}

Image Renderer::read_image() const {
  const int w = state_->scene.width, h = state_->scene.height;
  const size_t stride = size_t(w) * 4;
  Image img{w, h, std::vector<uint8_t>(stride * h)};
  // OSMesa stores GL's bottom-up rows; flip to top row first.
  for (int y = 0; y < h; ++y)
    std::memcpy(&img.rgba[size_t(y) * stride], &state_->colour[size_t(h - 1 - y) * stride], stride);
  return img;
}

size_t Renderer::triangles() const { return state_->mesh.triangles() * size_t(state_->scene.copies); }

std::string Renderer::gl_renderer() const {
  state_->make_current();
  const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return name ? name : "";
}

}  // namespace vref
