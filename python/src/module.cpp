// velocity._velocity: the Python bindings (pybind11). The public package, velocity/,
// re-exports these and adds RenderFlags, pose helpers and the batch runners.
//
// Threads: every call that renders or loads releases the GIL for its C++ part. A render
// first copies what it needs out of the scene (copy_scene, meshes shared, not copied)
// while it holds the GIL, so Python may change the scene meanwhile. One
// OffscreenRenderer renders one frame at a time (a mutex); many renderers render at
// once.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstring>
#include <mutex>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "convert.hpp"
#include "scene_graph.hpp"
#include "velocity/animation.hpp"
#include "velocity/error.hpp"
#include "velocity/load.hpp"
#include "velocity/log.hpp"
#include "velocity/png.hpp"
#include "velocity/texture.hpp"

namespace py = pybind11;
using namespace velocity;
using namespace velocity::python;

namespace {

// ---------------------------------------------------------------- warnings
// The core's warnings (a dropped NaN triangle, a missing texture) are collected per
// thread during a call and raised as Python warnings once the GIL is back; anything
// outside such a call goes to stderr as before.
thread_local std::vector<std::string>* t_warnings = nullptr;

struct CollectWarnings {
  std::vector<std::string> messages;
  CollectWarnings() { t_warnings = &messages; }
  ~CollectWarnings() { t_warnings = nullptr; }
  // Call with the GIL held.
  void emit() {
    for (const std::string& m : messages)
      if (PyErr_WarnEx(PyExc_RuntimeWarning, m.c_str(), 2) < 0) throw py::error_already_set();
    messages.clear();
  }
};

// ---------------------------------------------------------------- arrays
// numpy array -> ArrayView (native byte order; others are converted first).
ArrayView view_of(const py::array& a, const char* name) {
  if (a.ndim() != 2)
    throw py::value_error(std::string(name) + ": expected a 2-D array, got " + std::to_string(a.ndim()) + " dimensions");
  ArrayView v;
  v.data = a.data();
  v.kind = a.dtype().kind();
  v.itemsize = int(a.itemsize());
  v.rows = size_t(a.shape(0));
  v.cols = size_t(a.shape(1));
  v.row_stride = a.strides(0);
  v.col_stride = a.strides(1);
  return v;
}

py::array as_native(py::handle obj) {
  py::module_ np = py::module_::import("numpy");
  py::array a = np.attr("asarray")(obj);
  if (!a.dtype().attr("isnative").cast<bool>()) a = a.attr("astype")(a.dtype().attr("newbyteorder")("="));
  return a;
}

// A 4x4 pose from any array-like (None: the identity).
std::array<double, 16> pose_of(py::handle obj, const char* what) {
  std::array<double, 16> m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  if (obj.is_none()) return m;
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(obj);
  if (!a) throw py::type_error(std::string(what) + ": expected a 4x4 array");
  if (a.ndim() != 2 || a.shape(0) != 4 || a.shape(1) != 4)
    throw py::value_error(std::string(what) + ": expected shape (4, 4)");
  for (int i = 0; i < 16; ++i) {
    m[size_t(i)] = a.data()[i];
    if (!std::isfinite(m[size_t(i)])) throw py::value_error(std::string(what) + ": entries must be finite");
  }
  return m;
}

py::array_t<double> pose_array(const double* m) {
  py::array_t<double> a({4, 4});
  std::copy(m, m + 16, a.mutable_data());
  return a;
}

// A numpy array that owns `v` (moved in, not copied).
template <typename T>
py::array own(std::vector<T>&& v, std::vector<py::ssize_t> shape) {
  auto* heap = new std::vector<T>(std::move(v));
  py::capsule free_it(heap, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>(shape, heap->data(), free_it);
}

// A read-only numpy view of memory that `owner` keeps alive.
template <typename T>
py::array view(const T* data, std::vector<py::ssize_t> shape, std::shared_ptr<const void> owner) {
  auto* keep = new std::shared_ptr<const void>(std::move(owner));
  py::capsule base(keep, [](void* p) { delete static_cast<std::shared_ptr<const void>*>(p); });
  py::array a(py::dtype::of<T>(), shape, data, base);
  a.attr("setflags")(py::arg("write") = false);
  return a;
}

// pyrender's colour vectors: floats in [0, 1], or integers 0..255 (uint8 arrays, or a
// sequence of Python ints above 1).
std::array<double, 4> color_of(py::handle obj, const char* what, std::array<double, 4> fallback) {
  if (obj.is_none()) return fallback;
  py::array raw = as_native(obj);
  bool ints = raw.dtype().kind() == 'u' || raw.dtype().kind() == 'i';
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(raw);
  if (!a || a.ndim() != 1 || (a.shape(0) != 3 && a.shape(0) != 4))
    throw py::value_error(std::string(what) + ": expected 3 or 4 numbers");
  std::array<double, 4> c = fallback;
  bool over = false;
  for (py::ssize_t i = 0; i < a.shape(0); ++i) over |= a.data()[i] > 1;
  for (py::ssize_t i = 0; i < a.shape(0); ++i) {
    double v = a.data()[i];
    if (!std::isfinite(v) || v < 0) throw py::value_error(std::string(what) + ": entries must be finite and >= 0");
    c[size_t(i)] = ints && over ? v / 255.0 : v;
  }
  return c;
}

std::optional<Shading> shading_of(const std::string& name) {
  if (name == "color" || name == "unlit") return Shading::Unlit;
  std::optional<Shading> s = parse_shading(name);
  if (!s) throw py::value_error("shading: expected flat, gouraud, phong, unlit, wire or points, got '" + name + "'");
  return s;
}

// An H x W (x 1..4) uint8 image array as a texture (grey, grey+alpha, RGB or RGBA).
std::shared_ptr<const Texture> texture_of(py::handle obj, const char* what) {
  py::array raw = as_native(obj);
  if (raw.dtype().kind() == 'f') {  // floats in [0, 1], as pyrender accepts
    py::module_ np = py::module_::import("numpy");
    if (!np.attr("all")(np.attr("isfinite")(raw)).cast<bool>())
      throw py::value_error(std::string(what) + ": pixel values must be finite");
    raw = np.attr("clip")(np.attr("rint")(raw.attr("__mul__")(255.0)), 0, 255);
  }
  auto a = py::array_t<uint8_t, py::array::c_style | py::array::forcecast>::ensure(raw);
  if (!a) throw py::type_error(std::string(what) + ": expected an image array of numbers");
  if (a.ndim() != 2 && a.ndim() != 3)
    throw py::value_error(std::string(what) + ": expected an H x W or H x W x C image, got " + std::to_string(a.ndim()) +
                          " dimensions");
  const py::ssize_t h = a.shape(0), w = a.shape(1), c = a.ndim() == 3 ? a.shape(2) : 1;
  if (c < 1 || c > 4) throw py::value_error(std::string(what) + ": expected 1 to 4 channels, got " + std::to_string(c));
  if (h < 1 || w < 1 || h > 65536 || w > 65536)
    throw py::value_error(std::string(what) + ": expected 1..65536 pixels a side, got " + std::to_string(w) + " x " +
                          std::to_string(h));
  Image image{int(w), int(h)};
  const uint8_t* src = a.data();
  for (size_t i = 0, n = size_t(w) * size_t(h); i < n; ++i, src += c) {
    uint8_t* d = &image.pixels[i * 4];
    if (c <= 2) d[0] = d[1] = d[2] = src[0], d[3] = c == 2 ? src[1] : 255;
    else d[0] = src[0], d[1] = src[1], d[2] = src[2], d[3] = c == 4 ? src[3] : 255;
  }
  py::gil_scoped_release release;
  return std::make_shared<const Texture>(image);
}

std::optional<double> finite_or_none(std::optional<double> v, const char* what, double lo, double hi) {
  if (v && !(std::isfinite(*v) && *v >= lo && *v <= hi))
    throw py::value_error(std::string(what) + " must be in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                          "], got " + std::to_string(*v));
  return v;
}

// Camera parameters: a bad value is a ValueError naming it, from the constructor and
// from every setter alike (a setter puts the old value back).
template <class Cam>
void validate_camera(const Cam& c) {
  try {
    c.validate();
  } catch (const Error& e) {
    throw py::value_error(e.what());
  }
}
template <class C, class T>
auto checked_get(T C::*member) {
  return [member](const C& c) { return c.*member; };
}
template <class C, class T>
auto checked_set(T C::*member) {
  return [member](C& c, T value) {
    T old = c.*member;
    c.*member = value;
    try {
      validate_camera(c);
    } catch (...) {
      c.*member = old;
      throw;
    }
  };
}

// ---------------------------------------------------------------- meshes
struct PyMaterial {
  Material m;
};

struct PyMesh {
  std::shared_ptr<const MeshData> data;
};

struct PyPrimitive {
  std::shared_ptr<const MeshData> data;
  size_t index = 0;
  const Mesh& mesh() const { return *data->parts[index]; }
};

PyMesh py_mesh_from_arrays(py::object vertices, py::object faces, py::object normals, py::object uvs, py::object colors,
                        std::optional<PyMaterial> material, std::string name) {
  // Keep the converted arrays alive while their views are read.
  py::array v = as_native(vertices), f = as_native(faces);
  std::optional<py::array> n, u, c;
  MeshArrays in;
  in.vertices = view_of(v, "vertices");
  in.faces = view_of(f, "faces");
  if (!normals.is_none()) n = as_native(normals), in.normals = view_of(*n, "normals");
  if (!uvs.is_none()) u = as_native(uvs), in.uvs = view_of(*u, "uvs");
  if (!colors.is_none()) c = as_native(colors), in.colors = view_of(*c, "colors");
  auto mesh = std::make_shared<Mesh>(velocity::python::mesh_from_arrays(in, name));
  if (material) mesh->materials = {material->m};
  return {make_mesh_data(std::move(name), {mesh}, {Mat4::identity()})};
}

// Raises `type` with `message`, whose file names may not be UTF-8 (shown escaped).
void set_error(PyObject* type, const char* message) {
  PyObject* text = PyUnicode_DecodeUTF8(message, Py_ssize_t(std::strlen(message)), "backslashreplace");
  if (!text) return;  // the decoding's own error is set
  PyErr_SetObject(type, text);
  Py_DECREF(text);
}

// A file name as the OS has it: str (non-UTF-8 names as os.fsdecode gives them),
// bytes or os.PathLike, through os.fsencode.
std::string path_of(py::handle obj) {
  py::object encoded = py::module_::import("os").attr("fsencode")(obj);
  return std::string(encoded.cast<py::bytes>());
}

PyMesh mesh_from_file(py::object path_obj, bool swap_yz, double max_memory, std::optional<float> time,
                      std::optional<size_t> animation) {
  const std::string path = path_of(path_obj);
  Model model;
  {
    CollectWarnings warnings;
    {
      py::gil_scoped_release release;
      LoadOptions options;
      options.swap_yz = swap_yz;
      if (max_memory > 0) options.max_memory = size_t(max_memory);
      model = load_model(path, options);
    }
    warnings.emit();
  }
  // Every node's mesh with the node's world matrix (nodes come parents first).
  std::vector<Mat4> world(model.nodes.size());
  std::vector<std::shared_ptr<const Mesh>> parts;
  std::vector<Mat4> poses;
  for (size_t i = 0; i < model.nodes.size(); ++i) {
    const ModelNode& n = model.nodes[i];
    world[i] = n.parent < 0 ? n.local : world[size_t(n.parent)] * n.local;
    if (n.mesh && !n.mesh->triangles.empty()) parts.push_back(n.mesh), poses.push_back(world[i]);
  }
  if (time || animation) {
    // Posed as `velocity render --time` poses it: the nodes in a scene (node i is object
    // i), their matrices and morphed or skinned meshes at that time.
    Scene scene;
    add_to_scene(scene, model);
    try {
      pose_at(model.animations, animation.value_or(0), time.value_or(0.0f), model.skins, scene);
    } catch (const Error& e) {
      throw Error(path + ": " + e.what());
    }
    world = scene.world_matrices();
    parts.clear(), poses.clear();
    for (size_t i = 0; i < scene.objects().size(); ++i) {
      const std::shared_ptr<const Mesh>& mesh = scene.objects()[i].mesh;
      if (mesh && !mesh->triangles.empty()) parts.push_back(mesh), poses.push_back(world[i]);
    }
  }
  if (parts.empty()) throw Error(path + ": the file holds no triangles");
  // The name is the file's, as text (bytes that are not UTF-8 replaced).
  py::object os = py::module_::import("os");
  std::string name = py::str(os.attr("path").attr("basename")(os.attr("fsdecode")(path_obj)))
                         .attr("encode")("utf-8", "replace")
                         .cast<std::string>();
  return {make_mesh_data(name, std::move(parts), std::move(poses))};
}

PyMesh mesh_generated(Mesh mesh, std::string name) {
  mesh.name = name;
  return {make_mesh_data(std::move(name), {std::make_shared<const Mesh>(std::move(mesh))}, {Mat4::identity()})};
}

// ---------------------------------------------------------------- scene
struct PyScene;

struct PyNode {
  std::shared_ptr<SceneData> scene;
  uint32_t index = 0;
  NodeData& data() const { return scene->nodes[index]; }
};

struct PyScene {
  std::shared_ptr<SceneData> data = std::make_shared<SceneData>();

  NodeData& node(const PyNode& n) const {
    if (n.scene != data) throw py::value_error("the node belongs to another scene");
    if (n.data().removed) throw py::value_error("the node '" + n.data().name + "' was removed from the scene");
    return n.data();
  }

  PyNode add(py::object obj, std::optional<std::string> name, py::object pose, std::optional<PyNode> parent_node,
             std::optional<std::string> parent_name) {
    NodeData n;
    if (py::isinstance<PyMesh>(obj)) n.mesh = obj.cast<PyMesh&>().data;
    else if (py::isinstance<CameraBase>(obj)) n.camera = obj.cast<std::shared_ptr<CameraBase>>();
    else if (py::isinstance<LightBase>(obj)) n.light = obj.cast<std::shared_ptr<LightBase>>();
    else
      throw py::type_error("scene.add: expected a Mesh, a camera or a light, got " +
                           std::string(py::str(obj.get_type().attr("__name__"))));
    n.name = name ? *name : n.mesh ? n.mesh->name : n.camera ? n.camera->name : n.light->name;
    std::array<double, 16> p = pose_of(pose, "pose");
    std::copy(p.begin(), p.end(), n.pose);
    if (parent_node) {
      node(*parent_node);
      n.parent = parent_node->index;
    } else if (parent_name) {
      auto found = std::find_if(data->nodes.begin(), data->nodes.end(),
                                [&](const NodeData& d) { return !d.removed && d.name == *parent_name; });
      if (found == data->nodes.end()) throw py::value_error("no node named '" + *parent_name + "' in the scene");
      n.parent = found - data->nodes.begin();
    }
    if (data->nodes.size() >= UINT32_MAX - 1) throw py::value_error("too many nodes");
    bool camera = bool(n.camera);
    data->nodes.push_back(std::move(n));
    uint32_t index = uint32_t(data->nodes.size() - 1);
    if (camera && (data->main_camera < 0 || data->nodes[size_t(data->main_camera)].removed)) data->main_camera = index;
    return {data, index};
  }

  void remove(const PyNode& n) {
    node(n);
    // The node and everything below it (children come after their parents).
    std::vector<bool> gone(data->nodes.size(), false);
    gone[n.index] = true;
    for (size_t i = n.index; i < data->nodes.size(); ++i) {
      NodeData& d = data->nodes[i];
      if (d.parent >= 0 && gone[size_t(d.parent)]) gone[i] = true;
      if (gone[i]) d.removed = true;
    }
  }

  std::vector<PyNode> nodes(int kind) const {  // 0 all, 1 mesh, 2 camera, 3 light
    std::vector<PyNode> out;
    for (size_t i = 0; i < data->nodes.size(); ++i) {
      const NodeData& d = data->nodes[i];
      if (d.removed) continue;
      if (kind == 0 || (kind == 1 && d.mesh) || (kind == 2 && d.camera) || (kind == 3 && d.light))
        out.push_back({data, uint32_t(i)});
    }
    return out;
  }

  // World-space axis-aligned bounds of the visible meshes (pyrender's scene.bounds).
  std::array<std::array<double, 3>, 2> bounds() const {
    auto world = data->world_poses();
    bool any = false;
    std::array<std::array<double, 3>, 2> b{};
    for (size_t i = 0; i < data->nodes.size(); ++i) {
      const NodeData& d = data->nodes[i];
      if (d.removed || !d.mesh) continue;
      Mat4 w = to_mat4(world[i].data(), "pose");
      for (size_t p = 0; p < d.mesh->parts.size(); ++p) {
        Mat4 m = w * d.mesh->poses[p];
        for (Vec3 v : d.mesh->parts[p]->positions) {
          Vec3 q = m.transform_point(v);
          double c[3] = {q.x, q.y, q.z};
          for (int k = 0; k < 3; ++k) {
            if (!any) b[0][size_t(k)] = b[1][size_t(k)] = c[k];
            b[0][size_t(k)] = std::min(b[0][size_t(k)], c[k]);
            b[1][size_t(k)] = std::max(b[1][size_t(k)], c[k]);
          }
          any = true;
        }
      }
    }
    return b;
  }
};

// ---------------------------------------------------------------- renderer
// "cpu", "gpu" or "auto" (docs/gpu.md).
BackendChoice backend_choice(const std::string& name) {
  if (auto b = parse_backend(name)) return *b;
  throw Error("backend must be 'cpu', 'gpu' or 'auto', got '" + name + "'");
}

// The appearance options (RenderOptions; docs/appearance.md), by the names the CLI's
// --color, --tone-map, --exposure, --point-size take. Bad values are ValueErrors.
ColorPipeline color_pipeline(const std::string& name) {
  if (name == "auto") return ColorPipeline::Auto;
  if (name == "linear") return ColorPipeline::Linear;
  if (name == "display") return ColorPipeline::Display;
  throw py::value_error("color: expected 'auto', 'linear' or 'display', got '" + name + "'");
}
const char* to_string(ColorPipeline c) {
  return c == ColorPipeline::Linear ? "linear" : c == ColorPipeline::Display ? "display" : "auto";
}
ToneMap tone_map(const std::string& name) {
  if (name == "none") return ToneMap::None;
  if (name == "aces") return ToneMap::Aces;
  if (name == "neutral") return ToneMap::KhronosNeutral;
  throw py::value_error("tone_map: expected 'none', 'aces' or 'neutral', got '" + name + "'");
}
const char* to_string(ToneMap t) { return t == ToneMap::Aces ? "aces" : t == ToneMap::KhronosNeutral ? "neutral" : "none"; }
float exposure(double v) {
  if (!(std::isfinite(v) && v >= 0 && v <= 1e30)) throw py::value_error("exposure: expected a finite number >= 0, got " + py::repr(py::float_(v)).cast<std::string>());
  return float(v);
}
int shadow_map_size(int v) {
  if (v < 16 || v > 8192) throw py::value_error("shadow_map_size: expected 16..8192 texels a side, got " + std::to_string(v));
  return v;
}
float point_size(double v) {
  if (!(v >= 1 && v <= 64)) throw py::value_error("point_size: expected 1..64 pixels, got " + py::repr(py::float_(v)).cast<std::string>());
  return float(v);
}

struct PyRenderer {
  Renderer renderer;
  std::mutex mutex;
  std::shared_ptr<BufferPool> pool = std::make_shared<BufferPool>();
  // The last frame's options and its lights' shadows, as the engine got them (last_frame).
  std::optional<RenderOutput> last;
  PyRenderer(int w, int h, int ssaa, int threads, const std::string& backend)
      : renderer(w, h, backend_choice(backend)) {
    if (ssaa < 1 || ssaa > 4) throw Error("ssaa must be 1..4, got " + std::to_string(ssaa));
    if (threads < 0) throw Error("threads must be >= 0 (0: every core), got " + std::to_string(threads));
    renderer.options.ssaa = ssaa;
    renderer.options.threads = threads;
  }
  // Reads or changes the options between frames, never while another thread renders
  // (a frame changes them while it runs).
  template <typename F>
  auto with_options(F&& f) {
    py::gil_scoped_release release;  // never wait for the mutex holding the GIL
    std::lock_guard lock(mutex);
    return f(renderer.options);
  }
};


// pyrender's RenderFlags values that Velocity uses (velocity/__init__.py's RenderFlags).
enum : int64_t {
  kDepthOnly = 1,
  kAllWireframe = 8,
  kShadowsDirectional = 32,
  kShadowsPoint = 64,
  kShadowsSpot = 128,
  kSkipCullFaces = 1024,
  kRgba = 2048,
  kFlat = 4096,
  kSeg = 8192,
  kNormals = 1 << 20,
};

py::object render(PyRenderer& self, const PyScene& scene, int64_t flags, std::optional<std::string> pipeline) {
  RenderRequest req;
  req.color = !(flags & kDepthOnly);
  req.alpha = flags & kRgba;
  req.mask = flags & kSeg;
  req.normals = flags & kNormals;
  req.cull_back_faces = !(flags & kSkipCullFaces);
  if (flags & kAllWireframe) req.shading = Shading::Wireframe;
  else if (flags & kFlat) req.shading = Shading::Flat;
  req.shadows_directional = flags & kShadowsDirectional;
  req.shadows_point = flags & kShadowsPoint;
  req.shadows_spot = flags & kShadowsSpot;
  if (pipeline) req.color_pipeline = color_pipeline(*pipeline);
  RenderOutput out;
  int w, h;
  std::unique_ptr<uint8_t[]> color, depth_buffer;
  size_t color_bytes = 0, depth_bytes = 0;
  CollectWarnings warnings;
  {
    std::unique_lock lock(self.mutex, std::defer_lock);
    {
      py::gil_scoped_release release;
      lock.lock();  // without the GIL: another thread may be rendering with this renderer
    }
    w = self.renderer.width(), h = self.renderer.height();
    SceneCopy frame = copy_scene(*scene.data, w, h);  // with the GIL: the scene is Python's
    py::gil_scoped_release release;
    if (req.color) {
      color_bytes = size_t(w) * size_t(h) * 4;
      color = self.pool->take(color_bytes);
      req.color_buffer = color.get();
    }
    // Depth into a pooled buffer too (the same size as RGBA colour): no new pages to
    // fault in and no zeroing for every frame.
    depth_bytes = size_t(w) * size_t(h) * sizeof(float);
    depth_buffer = self.pool->take(depth_bytes);
    req.depth_buffer = reinterpret_cast<float*>(depth_buffer.get());
    out = render_frame(self.renderer, frame, req);
    self.last.emplace();
    self.last->options = out.options;
    self.last->cast_shadows = out.cast_shadows;
  }
  warnings.emit();
  // Each array owns its buffer; when numpy frees it, it goes back to the renderer's pool.
  struct Owner {
    std::shared_ptr<BufferPool> pool;
    std::unique_ptr<uint8_t[]> buffer;
    size_t bytes;
    ~Owner() { pool->give(std::move(buffer), bytes); }
  };
  auto pooled = [&](std::unique_ptr<uint8_t[]> buffer, size_t bytes) {
    auto* owner = new Owner{self.pool, std::move(buffer), bytes};
    return py::capsule(owner, [](void* p) { delete static_cast<Owner*>(p); });
  };
  const float* depth_values = req.depth_buffer;
  py::array depth = py::array_t<float>({py::ssize_t(h), py::ssize_t(w)}, depth_values, pooled(std::move(depth_buffer), depth_bytes));
  if (!req.color) return depth;
  py::list result;
  uint8_t* pixels = color.get();
  result.append(py::array_t<uint8_t>({py::ssize_t(h), py::ssize_t(w), py::ssize_t(req.alpha ? 4 : 3)}, pixels,
                                     pooled(std::move(color), color_bytes)));
  result.append(depth);
  if (req.mask) result.append(own(std::move(out.mask), {h, w}));
  if (req.normals) result.append(own(std::move(out.normals), {h, w, 3}));
  return py::tuple(result);
}

template <typename Cam>
py::array_t<double> projection_of(const Cam& cam, int width, int height) {
  cam.validate();
  Camera c;
  c.near = float(cam.znear);
  c.far = cam.zfar ? float(*cam.zfar) : 1e6f;
  cam.apply(c, width, height);
  Mat4 p = c.projection_matrix(float(width) / float(height));
  double m[16];
  for (int i = 0; i < 16; ++i) m[i] = p.m[i / 4][i % 4];
  return pose_array(m);
}

// numpy image -> PNG bytes (velocity.png.encode_png): the engine's encoder, run without the GIL.
py::bytes png_bytes(const py::array& image, int level, const std::string& filter) {
  static const std::pair<const char*, PngFilter> kFilters[] = {
      {"none", PngFilter::None}, {"sub", PngFilter::Sub}, {"up", PngFilter::Up},
      {"average", PngFilter::Average}, {"paeth", PngFilter::Paeth}, {"adaptive", PngFilter::Adaptive}};
  PngFilter f = PngFilter::Up;
  bool known = false;
  for (const auto& [name, value] : kFilters)
    if (filter == name) f = value, known = true;
  if (!known)
    throw py::value_error("encode_png: filter must be 'none', 'sub', 'up', 'average', 'paeth' or 'adaptive', got '" +
                          filter + "'");
  const bool u8 = image.dtype().is(py::dtype::of<uint8_t>()), u16 = image.dtype().is(py::dtype::of<uint16_t>());
  if (!u8 && !u16)
    throw DtypeError("encode_png: expected uint8 or uint16 pixels, got " + std::string(py::str(image.dtype())));
  const int channels = image.ndim() == 2 ? 1 : image.ndim() == 3 ? int(image.shape(2)) : 0;
  if (channels != 1 && channels != 3 && channels != 4) {
    std::string shape;
    for (py::ssize_t i = 0; i < image.ndim(); ++i) shape += (i ? ", " : "") + std::to_string(image.shape(i));
    throw ShapeError("encode_png: expected H x W, H x W x 1, H x W x 3 or H x W x 4, got shape (" + shape + ")");
  }
  if (u16 && channels != 1) throw ShapeError("encode_png: 16-bit images must be grey (H x W)");
  if (image.shape(0) < 1 || image.shape(1) < 1) throw ShapeError("encode_png: the image is empty");
  if (level < 0 || level > 9) throw py::value_error("encode_png: level must be 0..9 (zlib's), got " + std::to_string(level));
  py::array packed = py::array::ensure(image, py::array::c_style);  // rows of packed pixels
  PngImage im;
  im.pixels = packed.data();
  im.width = int(std::min<py::ssize_t>(packed.shape(1), 1 << 30));
  im.height = int(std::min<py::ssize_t>(packed.shape(0), 1 << 30));
  im.channels = channels;
  im.bits = u16 ? 16 : 8;
  im.stride = packed.shape(0) > 1 ? packed.strides(0) : ptrdiff_t(im.width) * channels * (im.bits / 8);
  std::vector<uint8_t> bytes;
  {
    py::gil_scoped_release release;
    bytes = encode_png(im, level, f);
  }
  return py::bytes(reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

}  // namespace

PYBIND11_MODULE(_velocity, m) {
  m.doc() = "Velocity's Python bindings (use the `velocity` package, which re-exports these).";
  static py::exception<Error> error(m, "Error", PyExc_RuntimeError);
  error.doc() = "An error from the Velocity engine; the message names the file, line or argument.";
  // Shape and element-type errors are ValueError and TypeError, as Python code expects,
  // and velocity.Error too.
  static py::object shape_error = py::reinterpret_steal<py::object>(PyErr_NewExceptionWithDoc(
      "velocity._velocity.ShapeError", "An array argument of the wrong shape (a ValueError and a velocity.Error).",
      py::make_tuple(error, py::handle(PyExc_ValueError)).ptr(), nullptr));
  static py::object dtype_error = py::reinterpret_steal<py::object>(PyErr_NewExceptionWithDoc(
      "velocity._velocity.DtypeError", "An array argument of the wrong element type (a TypeError and a velocity.Error).",
      py::make_tuple(error, py::handle(PyExc_TypeError)).ptr(), nullptr));
  m.attr("ShapeError") = shape_error;
  m.attr("DtypeError") = dtype_error;
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const ShapeError& e) {
      set_error(shape_error.ptr(), e.what());
    } catch (const DtypeError& e) {
      set_error(dtype_error.ptr(), e.what());
    } catch (const Error& e) {
      set_error(error.ptr(), e.what());
    }
  });
  set_warning_handler([](std::string_view message) {
    if (t_warnings) t_warnings->emplace_back(message);
    else std::fprintf(stderr, "velocity: warning: %.*s\n", int(message.size()), message.data());
  });

  py::class_<PyMaterial>(m, "Material", "How a mesh's surface is shaded (Velocity's fixed-function model, or "
                                          "glTF's metallic-roughness one when metallic or roughness is given).")
      .def(py::init([](py::object color, const std::string& shading, double specular, double shininess,
                       bool two_sided, py::object texture_obj, std::optional<double> metallic,
                       std::optional<double> roughness, double alpha, const std::string& alpha_mode,
                       double alpha_cutoff, py::object emissive, py::object image, const std::string& wrap,
                       const std::string& filter, const std::string& color_space) {
             PyMaterial pm;
             auto c = color_of(color, "color", {0.8, 0.8, 0.8, 1});
             pm.m.color = {float(c[0]), float(c[1]), float(c[2])};
             pm.m.shading = *shading_of(shading);
             if (!(specular >= 0 && std::isfinite(specular))) throw py::value_error("specular must be >= 0");
             if (!(shininess >= 0 && std::isfinite(shininess))) throw py::value_error("shininess must be >= 0");
             pm.m.specular = float(specular);
             pm.m.shininess = float(shininess);
             pm.m.two_sided = two_sided;
             finite_or_none(metallic, "metallic", 0, 1);
             finite_or_none(roughness, "roughness", 0, 1);
             if (metallic || roughness) {
               pm.m.shading = Shading::Pbr;
               pm.m.pbr.metallic = float(metallic.value_or(1.0));
               pm.m.pbr.roughness = float(roughness.value_or(1.0));
             }
             finite_or_none(alpha, "alpha", 0, 1);
             finite_or_none(alpha_cutoff, "alpha_cutoff", 0, 1);
             pm.m.alpha = float(alpha);
             pm.m.alpha_cutoff = float(alpha_cutoff);
             if (alpha_mode == "OPAQUE") pm.m.alpha_mode = AlphaMode::Opaque;
             else if (alpha_mode == "MASK") pm.m.alpha_mode = AlphaMode::Mask;
             else if (alpha_mode == "BLEND") pm.m.alpha_mode = AlphaMode::Blend;
             else throw py::value_error("alpha_mode: expected OPAQUE, MASK or BLEND, got '" + alpha_mode + "'");
             auto e = color_of(emissive, "emissive", {0, 0, 0, 1});
             pm.m.pbr.emissive = {float(e[0]), float(e[1]), float(e[2])};
             if (color_space == "srgb") pm.m.color_space = ColorSpace::Srgb;
             else if (color_space == "linear") pm.m.color_space = ColorSpace::Linear;
             else throw py::value_error("color_space: expected 'srgb' or 'linear', got '" + color_space + "'");
             if (wrap == "repeat") pm.m.wrap = Wrap::Repeat;
             else if (wrap == "clamp") pm.m.wrap = Wrap::Clamp;
             else if (wrap == "mirror") pm.m.wrap = Wrap::MirroredRepeat;
             else throw py::value_error("wrap: expected 'repeat', 'clamp' or 'mirror', got '" + wrap + "'");
             std::optional<Filter> f = parse_filter(filter);
             if (!f) throw py::value_error("filter: expected 'nearest', 'bilinear' or 'trilinear', got '" + filter + "'");
             pm.m.filter = *f;
             std::optional<std::string> texture;
             if (!texture_obj.is_none()) texture = path_of(texture_obj);
             if (texture && !image.is_none()) throw py::value_error("give texture (a file) or image (an array), not both");
             if (!image.is_none()) pm.m.texture = texture_of(image, "image");
             if (texture) {
               py::gil_scoped_release release;
               pm.m.texture = load_texture(*texture);
               pm.m.texture_file = *texture;
             }
             return pm;
           }),
           py::arg("color") = py::none(), py::arg("shading") = "gouraud", py::arg("specular") = 0.0,
           py::arg("shininess") = 32.0, py::arg("two_sided") = false, py::arg("texture") = py::none(),
           py::arg("metallic") = py::none(), py::arg("roughness") = py::none(), py::arg("alpha") = 1.0,
           py::arg("alpha_mode") = "OPAQUE", py::arg("alpha_cutoff") = 0.5, py::arg("emissive") = py::none(),
           py::arg("image") = py::none(), py::arg("wrap") = "repeat", py::arg("filter") = "trilinear",
           py::arg("color_space") = "srgb",
           "color: RGB in [0, 1] (or 0..255 integers); shading: 'flat', 'gouraud', 'phong', 'unlit', 'wire' "
           "or 'points'; specular: Ks of the white highlight Ks*(R.V)^shininess; two_sided: draw and light back "
           "faces; texture: an image file modulating the colour through the mesh's uvs (or image: an H x W x C "
           "array). metallic / roughness (0..1): glTF's metallic-roughness shading ('pbr') with these factors; "
           "alpha, alpha_mode ('OPAQUE', 'MASK', 'BLEND'), alpha_cutoff and emissive as glTF defines them; "
           "color_space: whether color is 'srgb' (display values) or 'linear' (glTF's factors).")
      .def_property_readonly("color", [](const PyMaterial& p) { return std::array<float, 3>{p.m.color.x, p.m.color.y, p.m.color.z}; })
      .def_property_readonly("shading", [](const PyMaterial& p) { return std::string(to_string(p.m.shading)); })
      .def_property_readonly("specular", [](const PyMaterial& p) { return p.m.specular; })
      .def_property_readonly("shininess", [](const PyMaterial& p) { return p.m.shininess; })
      .def_property_readonly("two_sided", [](const PyMaterial& p) { return p.m.two_sided; })
      .def_property_readonly("metallic", [](const PyMaterial& p) { return p.m.pbr.metallic; })
      .def_property_readonly("roughness", [](const PyMaterial& p) { return p.m.pbr.roughness; })
      .def_property_readonly("alpha", [](const PyMaterial& p) { return p.m.alpha; })
      .def_property_readonly("alpha_mode", [](const PyMaterial& p) {
        return std::string(p.m.alpha_mode == AlphaMode::Opaque ? "OPAQUE" : p.m.alpha_mode == AlphaMode::Mask ? "MASK" : "BLEND");
      })
      .def_property_readonly("emissive", [](const PyMaterial& p) {
        return std::array<float, 3>{p.m.pbr.emissive.x, p.m.pbr.emissive.y, p.m.pbr.emissive.z};
      })
      .def_property_readonly("color_space", [](const PyMaterial& p) {
        return std::string(p.m.color_space == ColorSpace::Srgb ? "srgb" : "linear");
      })
      .def_property_readonly("has_texture", [](const PyMaterial& p) { return bool(p.m.texture); })
      .def_property_readonly("texture", [](const PyMaterial& p) -> std::optional<std::string> {
        if (p.m.texture_file.empty()) return std::nullopt;
        return p.m.texture_file;
      });

  py::class_<PyPrimitive>(m, "Primitive",
                          "One part of a Mesh: its arrays are read-only views of the engine's own storage (no copy).")
      .def_property_readonly("positions", [](const PyPrimitive& p) {
        const Mesh& s = p.mesh();
        return view(&s.positions.data()->x, {py::ssize_t(s.positions.size()), 3}, p.data->parts[p.index]);
      }, "N x 3 float32 vertex positions (the part's own frame).")
      .def_property_readonly("normals", [](const PyPrimitive& p) -> py::object {
        const Mesh& s = p.mesh();
        if (s.normals.empty()) return py::none();
        return view(&s.normals.data()->x, {py::ssize_t(s.normals.size()), 3}, p.data->parts[p.index]);
      }, "N x 3 float32 unit normals.")
      .def_property_readonly("texcoord_0", [](const PyPrimitive& p) -> py::object {
        const Mesh& s = p.mesh();
        if (s.uvs.empty()) return py::none();
        return view(&s.uvs.data()->x, {py::ssize_t(s.uvs.size()), 2}, p.data->parts[p.index]);
      }, "N x 2 float32 texture coordinates, or None.")
      .def_property_readonly("color_0", [](const PyPrimitive& p) -> py::object {
        const Mesh& s = p.mesh();
        if (s.colors.empty()) return py::none();
        return view(&s.colors.data()->x, {py::ssize_t(s.colors.size()), 3}, p.data->parts[p.index]);
      }, "N x 3 float32 vertex colours in [0, 1], or None.")
      .def_property_readonly("indices", [](const PyPrimitive& p) {
        const Mesh& s = p.mesh();
        return view(&s.triangles.data()->v[0], {py::ssize_t(s.triangles.size()), 3}, p.data->parts[p.index]);
      }, "M x 3 uint32 vertex indices, counter-clockwise seen from the front.")
      .def_property_readonly("pose", [](const PyPrimitive& p) {
        double d[16];
        for (int i = 0; i < 16; ++i) d[i] = p.data->poses[p.index].m[i / 4][i % 4];
        return pose_array(d);
      }, "4x4 pose of the part in its mesh's frame.")
      .def_property_readonly("material", [](const PyPrimitive& p) -> std::optional<PyMaterial> {
        const Mesh& s = p.mesh();
        if (s.materials.empty()) return std::nullopt;
        return PyMaterial{s.materials[0]};
      }, "The part's first material, or None (the default grey).");

  py::class_<PyMesh>(m, "Mesh", "A renderable mesh: one or more primitives. Immutable; share it between scenes.")
      .def_static("from_arrays", &py_mesh_from_arrays, py::arg("vertices"), py::arg("faces"),
                  py::arg("normals") = py::none(), py::arg("uvs") = py::none(), py::arg("colors") = py::none(),
                  py::arg("material") = py::none(), py::arg("name") = "mesh",
                  "A mesh from numpy arrays: vertices N x 3 float, faces M x 3 integer (counter-clockwise front "
                  "faces), optional normals N x 3, uvs N x 2, colors N x 3/4 (float in [0, 1] or uint8).\n\n"
                  "float32 C-contiguous vertices, normals and uvs and (u)int32 faces are copied into the engine "
                  "with one memcpy each; other layouts and types are converted on the way. Without normals, "
                  "smooth ones are computed. Raises velocity.Error for a bad index or a non-finite value.")
      .def_static("from_file", &mesh_from_file, py::arg("path"), py::arg("swap_yz") = true,
                  py::arg("max_memory") = 0.0, py::arg("time") = py::none(), py::arg("animation") = py::none(),
                  "A mesh from a model file: ASC, PLG/PLX, OBJ (+MTL), glTF/GLB, 3DS, PLY or STL, every node "
                  "a primitive placed by its node matrix, textures found next to the file. Releases the GIL while "
                  "loading. swap_yz: stand 3D Studio ASC files (Z up) upright; max_memory: bytes the loader may "
                  "use (0: the engine's 2 GiB); time, animation: an animated glTF posed at `time` seconds of its "
                  "animation number `animation` (default 0; past the end: the last key), else at rest. Raises "
                  "velocity.Error naming the file, line and what was expected.")
      .def_static("sphere", [](int segments) { return mesh_generated(make_sphere(segments), "sphere"); },
                  py::arg("segments") = 64, "A UV sphere of radius 1: `segments` around, segments / 2 rings.")
      .def_static("cube", [](float size) { return mesh_generated(make_cube(size), "cube"); }, py::arg("size") = 1.0f,
                  "A cube `size` across, centred on the origin.")
      .def_static("torus", [](float major, float minor) { return mesh_generated(make_torus(major, minor), "torus"); },
                  py::arg("major") = 0.7f, py::arg("minor") = 0.3f, "A torus about the Y axis.")
      .def_property_readonly("name", [](const PyMesh& p) { return p.data->name; })
      .def_property_readonly("primitives", [](const PyMesh& p) {
        std::vector<PyPrimitive> out;
        for (size_t i = 0; i < p.data->parts.size(); ++i) out.push_back({p.data, i});
        return out;
      })
      .def_property_readonly("bounds", [](const PyMesh& p) {
        std::array<std::array<double, 3>, 2> b{};
        bool any = false;
        for (size_t i = 0; i < p.data->parts.size(); ++i)
          for (Vec3 v : p.data->parts[i]->positions) {
            Vec3 q = p.data->poses[i].transform_point(v);
            double c[3] = {q.x, q.y, q.z};
            for (size_t k = 0; k < 3; ++k) {
              if (!any) b[0][k] = b[1][k] = c[k];
              b[0][k] = std::min(b[0][k], c[k]), b[1][k] = std::max(b[1][k], c[k]);
            }
            any = true;
          }
        return b;
      }, "2 x 3: the minimum and maximum corner of the axis-aligned box.")
      .def_property_readonly("bounding_sphere", [](const PyMesh& p) {
        return py::make_tuple(std::array<float, 3>{p.data->bounds.center.x, p.data->bounds.center.y, p.data->bounds.center.z},
                              p.data->bounds.radius);
      }, "(centre, radius) of a sphere holding every vertex.")
      .def_property_readonly("triangle_count", [](const PyMesh& p) {
        size_t n = 0;
        for (const auto& part : p.data->parts) n += part->triangles.size();
        return n;
      })
      .def("__repr__", [](const PyMesh& p) {
        return "<velocity.Mesh '" + p.data->name + "' with " + std::to_string(p.data->parts.size()) + " primitive(s)>";
      });

  // Cameras.
  py::class_<CameraBase, std::shared_ptr<CameraBase>> camera(m, "Camera", "Base class of the cameras.");
  camera.def_readwrite("name", &CameraBase::name)
      .def_property("znear", checked_get(&CameraBase::znear), checked_set(&CameraBase::znear),
                    "Distance to the near clipping plane (> 0; a perspective camera's at least zfar / 1e5).")
      .def_property("zfar", checked_get(&CameraBase::zfar), checked_set(&CameraBase::zfar),
                    "Distance to the far plane (None: fitted to the scene).");
  py::class_<PerspectiveCamera, CameraBase, std::shared_ptr<PerspectiveCamera>>(m, "PerspectiveCamera",
      "A pinhole camera with a vertical field of view (pyrender's PerspectiveCamera). It looks down the -Z "
      "axis of its pose with +Y up.")
      .def(py::init([](double yfov, double znear, std::optional<double> zfar, std::optional<double> aspect,
                       std::optional<std::string> name) {
             auto c = std::make_shared<PerspectiveCamera>();
             c->yfov = yfov, c->znear = znear, c->zfar = zfar, c->aspect_ratio = aspect;
             if (name) c->name = *name;
             validate_camera(*c);
             return c;
           }),
           py::arg("yfov"), py::arg("znear") = 0.05, py::arg("zfar") = py::none(), py::arg("aspectRatio") = py::none(),
           py::arg("name") = py::none(),
           "yfov: vertical field of view in radians; aspectRatio: width / height (None: the image's); zfar None: "
           "just beyond the farthest mesh of the scene at each render.")
      .def_property("yfov", checked_get(&PerspectiveCamera::yfov), checked_set(&PerspectiveCamera::yfov))
      .def_property("aspectRatio", checked_get(&PerspectiveCamera::aspect_ratio),
                    checked_set(&PerspectiveCamera::aspect_ratio))
      .def("get_projection_matrix", &projection_of<PerspectiveCamera>, py::arg("width"), py::arg("height"),
           "The 4x4 OpenGL projection matrix for a width x height image (zfar None: 1e6 here).");
  py::class_<OrthographicCamera, CameraBase, std::shared_ptr<OrthographicCamera>>(m, "OrthographicCamera",
      "A parallel projection (pyrender's OrthographicCamera): the view volume is 2*xmag wide and 2*ymag high.")
      .def(py::init([](double xmag, double ymag, double znear, double zfar, std::optional<std::string> name) {
             auto c = std::make_shared<OrthographicCamera>();
             c->xmag = xmag, c->ymag = ymag, c->znear = znear, c->zfar = zfar;
             if (name) c->name = *name;
             validate_camera(*c);
             return c;
           }),
           py::arg("xmag"), py::arg("ymag"), py::arg("znear") = 0.05, py::arg("zfar") = 100.0,
           py::arg("name") = py::none())
      .def_property("xmag", checked_get(&OrthographicCamera::xmag), checked_set(&OrthographicCamera::xmag))
      .def_property("ymag", checked_get(&OrthographicCamera::ymag), checked_set(&OrthographicCamera::ymag))
      .def("get_projection_matrix", &projection_of<OrthographicCamera>, py::arg("width"), py::arg("height"));
  py::class_<IntrinsicsCamera, CameraBase, std::shared_ptr<IntrinsicsCamera>>(m, "IntrinsicsCamera",
      "A pinhole camera from intrinsics in pixels (pyrender's IntrinsicsCamera). Image coordinates run right "
      "and down from the top-left corner of the image, pixel (u, v)'s centre at (u + 0.5, v + 0.5), as in "
      "pyrender; for OpenCV's K (centres on whole numbers) use IntrinsicsCamera.from_K, which adds the 0.5.")
      .def(py::init([](double fx, double fy, double cx, double cy, double znear, double zfar,
                       std::optional<std::string> name) {
             auto c = std::make_shared<IntrinsicsCamera>();
             c->fx = fx, c->fy = fy, c->cx = cx, c->cy = cy, c->znear = znear, c->zfar = zfar;
             if (name) c->name = *name;
             validate_camera(*c);
             return c;
           }),
           py::arg("fx"), py::arg("fy"), py::arg("cx"), py::arg("cy"), py::arg("znear") = 0.05,
           py::arg("zfar") = 100.0, py::arg("name") = py::none())
      .def_property("fx", checked_get(&IntrinsicsCamera::fx), checked_set(&IntrinsicsCamera::fx))
      .def_property("fy", checked_get(&IntrinsicsCamera::fy), checked_set(&IntrinsicsCamera::fy))
      .def_property("cx", checked_get(&IntrinsicsCamera::cx), checked_set(&IntrinsicsCamera::cx))
      .def_property("cy", checked_get(&IntrinsicsCamera::cy), checked_set(&IntrinsicsCamera::cy))
      .def("get_projection_matrix", &projection_of<IntrinsicsCamera>, py::arg("width"), py::arg("height"));

  // Lights.
  py::class_<LightBase, std::shared_ptr<LightBase>> light(m, "Light", "Base class of the lights.");
  light.def_readwrite("name", &LightBase::name)
      .def_property("color", [](const LightBase& l) { return std::array<float, 3>{l.color.x, l.color.y, l.color.z}; },
                    [](LightBase& l, py::object c) {
                      auto v = color_of(c, "color", {1, 1, 1, 1});
                      l.color = {float(v[0]), float(v[1]), float(v[2])};
                    })
      .def_property("intensity", [](const LightBase& l) { return l.intensity; },
                    [](LightBase& l, double v) {
                      if (!(std::isfinite(v) && v >= 0)) throw py::value_error("intensity must be finite and >= 0, got " + std::to_string(v));
                      l.intensity = v;
                    })
      .def_readwrite("cast_shadows", &LightBase::cast_shadows,
                     "Whether it casts a shadow in frames with shadows (the renderer's shadows option, or a "
                     "RenderFlags.SHADOWS_* flag naming its kind); True by default.");
  auto make_light = [](auto l, py::object color, std::optional<double> intensity, std::optional<std::string> name) {
    auto v = color_of(color, "color", {1, 1, 1, 1});
    l->color = {float(v[0]), float(v[1]), float(v[2])};
    l->intensity = intensity.value_or(1.0);
    if (!(std::isfinite(l->intensity) && l->intensity >= 0)) throw py::value_error("intensity must be >= 0");
    if (name) l->name = *name;
    return l;
  };
  py::class_<DirectionalLight, LightBase, std::shared_ptr<DirectionalLight>>(m, "DirectionalLight",
      "A light from infinitely far away, shining along the -Z axis of its pose (pyrender's DirectionalLight). "
      "A Lambertian surface facing it gets albedo * color * intensity / pi.")
      .def(py::init([make_light](py::object color, std::optional<double> intensity, std::optional<std::string> name) {
             return make_light(std::make_shared<DirectionalLight>(), color, intensity, name);
           }),
           py::arg("color") = py::none(), py::arg("intensity") = py::none(), py::arg("name") = py::none());
  auto check_range = [](py::object range) -> std::optional<double> {
    if (range.is_none()) return std::nullopt;
    double r = range.cast<double>();
    if (!(std::isfinite(r) && r > 0)) throw py::value_error("range must be finite and > 0 (or None), got " + std::to_string(r));
    return r;
  };
  py::class_<PointLight, LightBase, std::shared_ptr<PointLight>>(m, "PointLight",
      "A light at the origin of its pose, falling off as 1 / d^2 (pyrender's PointLight); range: "
      "KHR_lights_punctual's cut-off distance (None: infinite).")
      .def(py::init([make_light, check_range](py::object color, std::optional<double> intensity, py::object range,
                                              std::optional<std::string> name) {
             auto l = make_light(std::make_shared<PointLight>(), color, intensity, name);
             l->range = check_range(range);
             return l;
           }),
           py::arg("color") = py::none(), py::arg("intensity") = py::none(), py::arg("range") = py::none(),
           py::arg("name") = py::none())
      .def_property("range", [](const PointLight& l) { return l.range; },
                    [check_range](PointLight& l, py::object r) { l.range = check_range(r); });
  py::class_<SpotLight, PointLight, std::shared_ptr<SpotLight>>(m, "SpotLight",
      "A point light shining along the -Z axis of its pose in a cone (pyrender's SpotLight): full intensity "
      "inside innerConeAngle, none outside outerConeAngle (half-angles, radians).")
      .def(py::init([make_light, check_range](py::object color, std::optional<double> intensity, py::object range,
                                              double inner, double outer, std::optional<std::string> name) {
             auto l = make_light(std::make_shared<SpotLight>(), color, intensity, name);
             l->range = check_range(range);
             l->inner_cone = inner, l->outer_cone = outer;
             try {
               l->validate();
             } catch (const Error& e) {
               throw py::value_error(e.what());
             }
             return l;
           }),
           py::arg("color") = py::none(), py::arg("intensity") = py::none(), py::arg("range") = py::none(),
           py::arg("innerConeAngle") = 0.0, py::arg("outerConeAngle") = std::numbers::pi / 4,
           py::arg("name") = py::none())
      .def_readonly("innerConeAngle", &SpotLight::inner_cone)
      .def_readonly("outerConeAngle", &SpotLight::outer_cone);

  // Nodes and scenes.
  py::class_<PyNode>(m, "Node", "A node of a Scene: one mesh, camera or light with a pose. `id` is what the "
                                "segmentation mask holds where the node's mesh is drawn.")
      .def_property_readonly("id", [](const PyNode& n) { return n.index + 1; })
      .def_property_readonly("name", [](const PyNode& n) { return n.data().name; })
      .def_property_readonly("mesh", [](const PyNode& n) -> std::optional<PyMesh> {
        if (!n.data().mesh) return std::nullopt;
        return PyMesh{n.data().mesh};
      })
      .def_property_readonly("camera", [](const PyNode& n) { return n.data().camera; })
      .def_property_readonly("light", [](const PyNode& n) { return n.data().light; })
      .def_property_readonly("matrix", [](const PyNode& n) { return pose_array(n.data().pose); },
                             "The pose relative to the parent node (4x4).")
      .def("__eq__", [](const PyNode& a, const PyNode& b) { return a.scene == b.scene && a.index == b.index; })
      .def("__hash__", [](const PyNode& n) { return py::hash(py::make_tuple(size_t(n.scene.get()), n.index)); })
      .def("__repr__", [](const PyNode& n) {
        return "<velocity.Node " + std::to_string(n.index + 1) + " '" + n.data().name + "'>";
      });

  py::class_<PyScene>(m, "Scene", "Meshes, cameras and lights in a node hierarchy (pyrender's Scene).")
      .def(py::init([](py::object bg_color, py::object ambient_light) {
             PyScene s;
             auto bg = color_of(bg_color, "bg_color", {1, 1, 1, 1});
             std::copy(bg.begin(), bg.end(), s.data->bg_color);
             auto a = color_of(ambient_light, "ambient_light", {0, 0, 0, 1});
             s.data->ambient = {float(a[0]), float(a[1]), float(a[2])};
             return s;
           }),
           py::arg("bg_color") = py::none(), py::arg("ambient_light") = py::none(),
           "bg_color: RGBA background (default white, opaque); ambient_light: RGB ambient light (default none).")
      .def("add", &PyScene::add, py::arg("obj"), py::arg("name") = py::none(), py::arg("pose") = py::none(),
           py::arg("parent_node") = py::none(), py::arg("parent_name") = py::none(),
           "Adds a Mesh, camera or light at `pose` (4x4, relative to the parent; None: identity) and returns "
           "its Node. The first camera added becomes the main camera.")
      .def("set_pose", [](PyScene& s, const PyNode& n, py::object pose) {
             auto p = pose_of(pose, "pose");
             std::copy(p.begin(), p.end(), s.node(n).pose);
           }, py::arg("node"), py::arg("pose"), "Sets the node's pose relative to its parent.")
      .def("get_pose", [](const PyScene& s, const PyNode& n) {
             s.node(n);
             auto world = s.data->world_poses();
             return pose_array(world[n.index].data());
           }, py::arg("node"), "The node's world pose (parents applied).")
      .def("remove_node", &PyScene::remove, py::arg("node"), "Removes the node and its descendants.")
      .def("has_node", [](const PyScene& s, const PyNode& n) { return n.scene == s.data && !n.data().removed; },
           py::arg("node"))
      .def_property("main_camera_node",
                    [](const PyScene& s) -> std::optional<PyNode> {
                      if (s.data->main_camera < 0 || s.data->nodes[size_t(s.data->main_camera)].removed) return std::nullopt;
                      return PyNode{s.data, uint32_t(s.data->main_camera)};
                    },
                    [](PyScene& s, const PyNode& n) {
                      if (!s.node(n).camera) throw py::value_error("main_camera_node must be a camera node");
                      s.data->main_camera = n.index;
                    })
      .def_property_readonly("nodes", [](const PyScene& s) { return s.nodes(0); })
      .def_property_readonly("mesh_nodes", [](const PyScene& s) { return s.nodes(1); })
      .def_property_readonly("camera_nodes", [](const PyScene& s) { return s.nodes(2); })
      .def_property_readonly("light_nodes", [](const PyScene& s) { return s.nodes(3); })
      .def("get_nodes", [](const PyScene& s, std::optional<std::string> name) {
             std::vector<PyNode> out;
             for (const PyNode& n : s.nodes(0))
               if (!name || n.data().name == *name) out.push_back(n);
             return out;
           }, py::arg("name") = py::none())
      .def_property("bg_color",
                    [](const PyScene& s) { return std::array<double, 4>{s.data->bg_color[0], s.data->bg_color[1], s.data->bg_color[2], s.data->bg_color[3]}; },
                    [](PyScene& s, py::object c) {
                      auto bg = color_of(c, "bg_color", {1, 1, 1, 1});
                      std::copy(bg.begin(), bg.end(), s.data->bg_color);
                    })
      .def_property("ambient_light",
                    [](const PyScene& s) { return std::array<float, 3>{s.data->ambient.x, s.data->ambient.y, s.data->ambient.z}; },
                    [](PyScene& s, py::object c) {
                      auto a = color_of(c, "ambient_light", {0, 0, 0, 1});
                      s.data->ambient = {float(a[0]), float(a[1]), float(a[2])};
                    })
      .def_property_readonly("bounds", &PyScene::bounds, "2 x 3: the world-space box around every mesh.");

  py::class_<PyRenderer>(m, "OffscreenRenderer",
      "Renders scenes to numpy arrays on the CPU (pyrender's OffscreenRenderer; no display, no GL). Many "
      "renderers may render at once from many threads; the GIL is released while one renders.")
      .def(py::init([](int w, int h, int ssaa, int threads, const std::string& backend, const std::string& color,
                       const std::string& tone, double exp, bool shadows, int map_size, double points) {
             // The options first: a bad one is a ValueError before any backend starts.
             RenderOptions o;
             o.color = color_pipeline(color), o.tone_map = tone_map(tone), o.exposure = exposure(exp);
             o.shadows = shadows, o.shadow_map_size = shadow_map_size(map_size), o.point_size = point_size(points);
             auto r = std::make_unique<PyRenderer>(w, h, ssaa, threads, backend);
             RenderOptions& ro = r->renderer.options;
             ro.color = o.color, ro.tone_map = o.tone_map, ro.exposure = o.exposure;
             ro.shadows = o.shadows, ro.shadow_map_size = o.shadow_map_size, ro.point_size = o.point_size;
             return r;
           }),
           py::arg("viewport_width"), py::arg("viewport_height"), py::arg("ssaa") = 1, py::arg("threads") = 0,
           py::arg("backend") = "cpu", py::kw_only(), py::arg("color") = "auto", py::arg("tone_map") = "none",
           py::arg("exposure") = 1.0, py::arg("shadows") = false, py::arg("shadow_map_size") = 2048,
           py::arg("point_size") = 1.0,
           "viewport_width x viewport_height pixels (1..16384); ssaa: 1..4 samples per side per pixel (colour "
           "averaged; depth and mask from the nearest sample, never blended); threads: cores for one frame "
           "(0: all); backend: 'cpu', 'gpu' (OpenGL 3.3 through EGL; an error naming what is missing) or "
           "'auto' (a hardware GPU, else the CPU). The appearance options (keywords, also properties): color, "
           "tone_map, exposure, shadows, shadow_map_size, point_size.")
      .def_property("viewport_width", [](PyRenderer& r) { return r.renderer.width(); },
                    [](PyRenderer& r, int w) {
                      py::gil_scoped_release release;  // never wait for the mutex holding the GIL
                      std::lock_guard lock(r.mutex);
                      r.renderer.resize(w, r.renderer.height());
                    })
      .def_property("viewport_height", [](PyRenderer& r) { return r.renderer.height(); },
                    [](PyRenderer& r, int h) {
                      py::gil_scoped_release release;
                      std::lock_guard lock(r.mutex);
                      r.renderer.resize(r.renderer.width(), h);
                    })
      .def_property("color", [](PyRenderer& r) { return std::string(to_string(r.with_options([](RenderOptions& o) { return o.color; }))); },
                    [](PyRenderer& r, const std::string& v) { auto c = color_pipeline(v); r.with_options([&](RenderOptions& o) { o.color = c; }); },
                    "'auto' (linear for a frame with PBR materials, else display), 'linear' (sRGB decoded, lit in "
                    "linear light, encoded) or 'display' (8-bit values lit as they are, as OpenGL 1.x).")
      .def_property("tone_map", [](PyRenderer& r) { return std::string(to_string(r.with_options([](RenderOptions& o) { return o.tone_map; }))); },
                    [](PyRenderer& r, const std::string& v) { auto t = tone_map(v); r.with_options([&](RenderOptions& o) { o.tone_map = t; }); },
                    "Tone mapping in the linear pipeline: 'none', 'aces' (as three.js) or 'neutral' (Khronos PBR Neutral).")
      .def_property("exposure", [](PyRenderer& r) { return r.with_options([](RenderOptions& o) { return o.exposure; }); },
                    [](PyRenderer& r, double v) { float e = exposure(v); r.with_options([&](RenderOptions& o) { o.exposure = e; }); },
                    "Linear light is multiplied by this before tone mapping (>= 0).")
      .def_property("shadows", [](PyRenderer& r) { return r.with_options([](RenderOptions& o) { return o.shadows; }); },
                    [](PyRenderer& r, bool v) { r.with_options([&](RenderOptions& o) { o.shadows = v; }); },
                    "Shadow maps for every light whose cast_shadows is on (RenderFlags.SHADOWS_* turn them on for "
                    "one frame and one kind of light).")
      .def_property("shadow_map_size", [](PyRenderer& r) { return r.with_options([](RenderOptions& o) { return o.shadow_map_size; }); },
                    [](PyRenderer& r, int v) { int n = shadow_map_size(v); r.with_options([&](RenderOptions& o) { o.shadow_map_size = n; }); },
                    "Texels a side of each shadow map, 16..8192.")
      .def_property("point_size", [](PyRenderer& r) { return r.with_options([](RenderOptions& o) { return o.point_size; }); },
                    [](PyRenderer& r, double v) { float p = point_size(v); r.with_options([&](RenderOptions& o) { o.point_size = p; }); },
                    "Side of a point (point clouds, points shading) in output pixels, 1..64.")
      .def_property_readonly("last_frame", [](PyRenderer& r) -> py::object {
        std::optional<RenderOutput> last;
        const char *backend = nullptr, *reason = nullptr;
        {
          py::gil_scoped_release release;
          std::lock_guard lock(r.mutex);  // not while a frame writes them
          if (r.last) last.emplace(), last->options = r.last->options, last->cast_shadows = r.last->cast_shadows;
          backend = r.renderer.stats().backend, reason = r.renderer.stats().backend_reason;
        }
        if (!last) return py::none();
        const RenderOptions& o = last->options;
        py::dict d;
        d["backend"] = backend;
        d["backend_reason"] = reason;
        d["color"] = to_string(o.color);
        d["tone_map"] = to_string(o.tone_map);
        d["exposure"] = o.exposure;
        d["shadows"] = o.shadows;
        d["shadow_map_size"] = o.shadow_map_size;
        d["point_size"] = o.point_size;
        d["cast_shadows"] = py::cast(last->cast_shadows);
        return d;
      }, "What the engine was given for the last frame, as a dict (None before the first): backend and "
         "backend_reason (which backend drew and why), color, tone_map, exposure, shadows, shadow_map_size, "
         "point_size, and cast_shadows, per light in the scene's order (the ambient term last).")
      .def("_render", &render, py::arg("scene"), py::arg("flags"), py::arg("color") = py::none())
      .def("delete", [](PyRenderer&) {}, "Nothing to free (pyrender needs this; kept for its users).");

  m.def("_camera_pose_angles", [](py::object pose) {
    auto p = pose_of(pose, "pose");
    CameraPose c = camera_pose(p.data());
    return py::make_tuple(std::array<float, 3>{c.position.x, c.position.y, c.position.z}, c.yaw, c.pitch, c.roll);
  }, "Internal: (position, yaw, pitch, roll) the engine's camera takes for a camera pose.");
  m.def("encode_png", &png_bytes, py::arg("image"), py::arg("level") = 3, py::arg("filter") = "up",
        "PNG bytes of a uint8 H x W (grey), H x W x 3 (RGB) or H x W x 4 (RGBA) image, or a uint16 H x W one "
        "(16-bit grey). level: zlib's, 0..9; filter: one PNG row filter for every row ('up', the default, "
        "suits rendered frames), or 'adaptive' (libpng's choice per row: smaller, slower). The engine's encoder "
        "(velocity::encode_png, libpng) encodes; the GIL is released meanwhile.");
  m.def("_rotation_from_angles", [](double yaw, double pitch, double roll) {
    double r[9];
    rotation_from_angles(yaw, pitch, roll, r);
    return std::array<double, 9>{r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8]};
  });
}
