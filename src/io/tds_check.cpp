// The 3D Studio chunk check (see tds_check.hpp for why it exists). Chunk ids and
// layouts as in Autodesk's 3DS file toolkit and as Assimp's 3DS reader uses them; a
// chunk id that is not listed here is checked to lie inside its parent and not entered.
#include "io/tds_check.hpp"

#include <cstdint>
#include <cstdio>

#include "velocity/error.hpp"

namespace velocity::detail {

namespace {

enum : uint16_t {
  kMain = 0x4d4d,
  kEditor = 0x3d3d,
  kObject = 0x4000,       // NUL-terminated name, then sub-chunks
  kTriMesh = 0x4100,
  kVertices = 0x4110,     // u16 count, count x 3 floats
  kFaces = 0x4120,        // u16 count, count x (3 u16 corners + u16 flags), then sub-chunks
  kFaceMaterial = 0x4130, // name, u16 count, count x u16 face
  kUvs = 0x4140,          // u16 count, count x 2 floats
  kSmoothing = 0x4150,    // one u32 per face
  kLight = 0x4600,        // 3 floats, then sub-chunks
  kCamera = 0x4700,       // 8 floats, then sub-chunks
  kMaterial = 0xafff,
  kMaterialName = 0xa000,
  kKeyframer = 0xb000,
  kFirstNodeTag = 0xb001,  // ambient, object, camera, target, light, light target, spot
  kLastNodeTag = 0xb007,
  kNodeHeader = 0xb010,   // name, 3 u16
  kFirstTrack = 0xb020,   // position, rotation, scale, fov, roll, colour, morph, hotspot,
  kLastTrack = 0xb029,    // falloff, hide: u16 flags, 8 bytes, u32 key count, keys
};

constexpr int kMaxDepth = 16;  // real files nest 5 deep

class Walker {
 public:
  Walker(std::string_view bytes, const std::string& path) : b_(bytes), path_(path) {}

  void main() {
    if (b_.size() < 6) fail(0, "the file is " + std::to_string(b_.size()) + " bytes, too short for a 3DS chunk");
    if (u16(0) != kMain) fail(0, "the file does not start with a 3DS main chunk (0x4d4d)");
    children(6, chunk_end(0, b_.size()), 0, 0);
  }

 private:
  uint16_t u16(size_t at) const { return uint16_t(uint8_t(b_[at]) | uint8_t(b_[at + 1]) << 8); }
  uint32_t u32(size_t at) const { return uint32_t(u16(at)) | uint32_t(u16(at + 2)) << 16; }

  [[noreturn]] void fail(size_t at, const std::string& what) const {
    throw Error(path_ + ": byte " + std::to_string(at) + ": " + what + " (3DS file truncated or damaged?)");
  }
  static std::string hex(uint16_t id) {
    char s[8];
    std::snprintf(s, sizeof s, "0x%04x", id);
    return s;
  }

  // The end of the chunk at `at`, which must lie inside [at, parent_end).
  size_t chunk_end(size_t at, size_t parent_end) const {
    if (parent_end - at < 6) fail(at, "a chunk header needs 6 bytes, " + std::to_string(parent_end - at) + " are left");
    uint32_t length = u32(at + 2);
    if (length < 6 || length > parent_end - at)
      fail(at, "chunk " + hex(u16(at)) + " has length " + std::to_string(length) + ", but its parent has " +
                   std::to_string(parent_end - at) + " bytes left");
    return at + length;
  }

  // The offset just past the NUL ending the string at `at`, which must end before `end`.
  size_t string_end(size_t at, size_t end, uint16_t id) const {
    for (size_t i = at; i < end; ++i)
      if (b_[i] == '\0') return i + 1;
    fail(at, "the name in chunk " + hex(id) + " does not end inside the chunk");
  }

  // `count` items of `size` bytes from `at` must end by `end`; returns their end.
  size_t array_end(size_t at, size_t end, uint64_t count, size_t size, uint16_t id, const char* what) const {
    if (count * size > end - at)
      fail(at, "chunk " + hex(id) + " claims " + std::to_string(count) + " " + what + " (" +
                   std::to_string(count * size) + " bytes), but holds " + std::to_string(end - at));
    return at + size_t(count * size);
  }

  // The chunks in [at, end). `faces`: the face count of the enclosing face list.
  void children(size_t at, size_t end, int depth, uint64_t faces) {
    if (depth > kMaxDepth) fail(at, "chunks nest deeper than " + std::to_string(kMaxDepth));
    while (at < end) {
      const size_t next = chunk_end(at, end);  // checks the 6 header bytes are there
      const uint16_t id = u16(at);
      const size_t data = at + 6;
      switch (id) {
        case kEditor: case kTriMesh: case kMaterial: case kKeyframer:
          children(data, next, depth + 1, 0);
          break;
        case kObject:
          children(string_end(data, next, id), next, depth + 1, 0);
          break;
        case kVertices:
          if (next - data < 2) fail(data, "chunk " + hex(id) + " has no count");
          array_end(data + 2, next, u16(data), 12, id, "vertices");
          break;
        case kUvs:
          if (next - data < 2) fail(data, "chunk " + hex(id) + " has no count");
          array_end(data + 2, next, u16(data), 8, id, "uvs");
          break;
        case kFaces: {
          if (next - data < 2) fail(data, "chunk " + hex(id) + " has no count");
          const uint16_t n = u16(data);
          children(array_end(data + 2, next, n, 8, id, "faces"), next, depth + 1, n);
          break;
        }
        case kFaceMaterial: {
          size_t after = string_end(data, next, id);
          if (next - after < 2) fail(after, "chunk " + hex(id) + " has no count");
          array_end(after + 2, next, u16(after), 2, id, "face indices");
          break;
        }
        case kSmoothing:
          array_end(data, next, faces, 4, id, "smoothing groups");
          break;
        case kLight:
          if (next - data < 12) fail(data, "light chunk " + hex(id) + " is too short");
          children(data + 12, next, depth + 1, 0);
          break;
        case kCamera:
          if (next - data < 32) fail(data, "camera chunk " + hex(id) + " is too short");
          children(data + 32, next, depth + 1, 0);
          break;
        case kMaterialName:
          string_end(data, next, id);
          break;
        case kNodeHeader:
          array_end(string_end(data, next, id), next, 3, 2, id, "header values");
          break;
        default:
          if (id >= kFirstNodeTag && id <= kLastNodeTag) {
            children(data, next, depth + 1, 0);
          } else if (id >= kFirstTrack && id <= kLastTrack) {
            // Each key is at least a u32 frame and u16 flags.
            if (next - data < 14) fail(data, "track chunk " + hex(id) + " is too short");
            array_end(data + 14, next, u32(data + 10), 6, id, "keys");
          }
          break;
      }
      at = next;
    }
  }

  std::string_view b_;
  const std::string& path_;
};

}  // namespace

void check_3ds(std::string_view bytes, const std::string& path) { Walker(bytes, path).main(); }

}  // namespace velocity::detail
