// The PLG / PLX reader: comments, descriptors bit by bit, both dialects' windings,
// triangulation, errors, the HTML impostor, truncated and damaged input.
#include <gtest/gtest.h>

#include <string>

#include "io/plg.hpp"
#include "loader_test_util.hpp"
#include "velocity/load.hpp"

namespace velocity {
namespace {

using detail::PlgDialect;
using detail::plg_material;
using detail::vga_palette;
using test::loads_or_throws_error;
using test::read_bytes;
using test::shared_data;

std::string error_of(std::string_view text, const std::string& name = "t.plg") {
  try {
    parse_plg(text, name);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

Mesh only_mesh(const Model& m) {  // a copy: the model may be a temporary
  EXPECT_EQ(m.nodes.size(), 1u);
  return *m.nodes.at(0).mesh;
}

// Cube [-1, 1]^3 with its six quads' corners in `order` (a permutation of 0..3 applied
// to a counter-clockwise-from-outside, right-handed listing).
std::string cube_plg(bool reverse, const std::string& descriptor, const std::string& comment) {
  const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  std::string s = comment;
  s += " a cube\ncube 8 6\n";
  for (int i = 0; i < 8; ++i) {
    s += (i & 1) ? "1 " : "-1 ";
    s += (i & 2) ? "1 " : "-1 ";
    s += (i & 4) ? "1\n" : "-1\n";
  }
  for (const auto& q : quads) {
    s += descriptor;
    s += " 4";
    for (int k = 0; k < 4; ++k) {
      s += ' ';
      s += std::to_string(q[reverse ? 3 - k : k]);
    }
    s += '\n';
  }
  return s;
}

// Every face's normal points away from the mesh's bounding-box centre.
void expect_all_faces_outwards(const Mesh& mesh, const std::string& what) {
  Vec3 c = mesh.bounds().center();
  for (size_t f = 0; f < mesh.triangle_count(); ++f) {
    const Triangle& t = mesh.triangles[f];
    Vec3 centroid = (mesh.positions[t.v[0]] + mesh.positions[t.v[1]] + mesh.positions[t.v[2]]) / 3.0f;
    EXPECT_GT(dot(face_normal(mesh, t), centroid - c), 0.0f) << what << ": triangle " << f << " faces inwards";
  }
}

// ---- syntax -------------------------------------------------------------------------------

TEST(Plg, ParsesCommentsHexAndDecimalDescriptorsAndMixedPolygons) {
  const char* text =
      "; PYRAMID object\n"
      "\n"
      "PYRAMID 5 3   ; trailing comment\n"
      "  0 10  0\n"
      "-10  0 -10\n"
      "\t10 0 -10\n"
      "10  0  10 \n"
      "-10 0 10\n"
      "\n"
      "0x102f 3 0 1 2\n"
      "12  3 0 2 3   ; decimal\n"
      "0X10AF 4 4 3 2 1 \n"
      "; end of PYRAMID\n";
  Model m = parse_plg(text, "p.plg");
  const Mesh& mesh = only_mesh(m);
  EXPECT_EQ(m.nodes[0].name, "PYRAMID");
  EXPECT_EQ(mesh.vertex_count(), 5u);
  EXPECT_EQ(mesh.triangle_count(), 1u + 1u + 2u);  // the quad is fanned into two
  ASSERT_EQ(mesh.materials.size(), 3u);            // one per distinct descriptor
  EXPECT_EQ(mesh.materials[0].name, "0x102f");
  EXPECT_EQ(mesh.materials[1].name, "0x000c");
  EXPECT_EQ(mesh.materials[2].name, "0x10af");
  EXPECT_EQ(mesh.face_materials, (std::vector<uint32_t>{0, 1, 2, 2}));
  EXPECT_EQ(mesh.normals.size(), 5u);
  EXPECT_NO_THROW(mesh.validate());
}

TEST(Plg, CrlfAndFloatCoordinatesAndHashComments) {
  const char* text =
      "# begin plg/plx file\r\n"
      "# define PLX_RGB_MASK 0x8000 // this poly uses RGB color\r\n"
      "tri 3 1   \r\n"
      " 5.5  5 -2.25e1\r\n"
      "-5  5 5\r\n"
      "-5 -5 5\r\n"
      "0xd0f0 3 2 1 0 \r\n"
      "#end poly list";
  const Mesh& mesh = only_mesh(parse_plg(text, "t.plg"));
  EXPECT_EQ(mesh.positions[0], (Vec3{5.5f, 5, 22.5f}));  // z negated: left- to right-handed
}

TEST(Plg, FanTriangulatesConvexPolygonsAndSkipsPointsAndLines) {
  const char* text =
      "penta 5 3\n"
      "0 0 0\n1 0 0\n1 1 0\n0.5 1.5 0\n0 1 0\n"
      "0x1010 5 0 1 2 3 4\n"
      "0x1010 2 0 1\n"  // a line: nothing to fill
      "0x1010 1 3\n";   // a point
  const Mesh& mesh = only_mesh(parse_plg(text, "t.plg"));
  ASSERT_EQ(mesh.triangle_count(), 3u);
  // Black Art order kept, fanned from the first vertex.
  EXPECT_EQ(mesh.triangles[0].v[0], 0u);
  EXPECT_EQ(mesh.triangles[0].v[1], 1u);
  EXPECT_EQ(mesh.triangles[0].v[2], 2u);
  EXPECT_EQ(mesh.triangles[2].v[1], 3u);
  EXPECT_EQ(mesh.triangles[2].v[2], 4u);
}

// ---- descriptors ----------------------------------------------------------------------------

TEST(Plg, VgaDefaultPaletteSpotChecks) {
  // Values from the IBM VGA default palette (6-bit DAC units / 63).
  auto rgb = [](int r, int g, int b) { return Vec3{float(r), float(g), float(b)} / 63.0f; };
  EXPECT_EQ(vga_palette(0), rgb(0, 0, 0));
  EXPECT_EQ(vga_palette(1), rgb(0, 0, 42));
  EXPECT_EQ(vga_palette(6), rgb(42, 21, 0));     // EGA brown
  EXPECT_EQ(vga_palette(15), rgb(63, 63, 63));
  EXPECT_EQ(vga_palette(16), rgb(0, 0, 0));      // grey ramp
  EXPECT_EQ(vga_palette(23), rgb(24, 24, 24));
  EXPECT_EQ(vga_palette(31), rgb(63, 63, 63));
  EXPECT_EQ(vga_palette(32), rgb(0, 0, 63));     // high intensity, high saturation: blue
  EXPECT_EQ(vga_palette(33), rgb(16, 0, 63));
  EXPECT_EQ(vga_palette(40), rgb(63, 0, 0));     // red
  EXPECT_EQ(vga_palette(44), rgb(63, 63, 0));    // yellow
  EXPECT_EQ(vga_palette(48), rgb(0, 63, 0));     // green
  EXPECT_EQ(vga_palette(81), rgb(49, 45, 63));
  EXPECT_EQ(vga_palette(104), rgb(0, 0, 28));
  EXPECT_EQ(vga_palette(159), rgb(28, 20, 22));  // 0x9f, Black Art's "SHADE_BLUE"
  EXPECT_EQ(vga_palette(227), rgb(15, 11, 16));
  EXPECT_EQ(vga_palette(247), rgb(11, 12, 16));
  EXPECT_EQ(vga_palette(248), rgb(0, 0, 0));
  EXPECT_EQ(vga_palette(255), rgb(0, 0, 0));
}

TEST(Plg, BlackArtDescriptorBits) {
  // 0x109f: flat shading (top nibble 1), one-sided (bits 8-11 zero), colour 0x9f.
  Material m = plg_material(0x109f, PlgDialect::BlackArt);
  EXPECT_EQ(m.name, "0x109f");
  EXPECT_EQ(m.shading, Shading::Flat);
  EXPECT_FALSE(m.two_sided);
  EXPECT_EQ(m.color, vga_palette(0x9f));
  // Constant shading (0) is drawn unlit; bits 8-11 make a polygon two-sided.
  Material c = plg_material(0x0112, PlgDialect::BlackArt);
  EXPECT_EQ(c.shading, Shading::Unlit);
  EXPECT_TRUE(c.two_sided);
  EXPECT_EQ(c.color, vga_palette(0x12));
  EXPECT_TRUE(plg_material(0x0f00, PlgDialect::BlackArt).two_sided);
  EXPECT_FALSE(plg_material(0x30ff, PlgDialect::BlackArt).two_sided);
  EXPECT_EQ(plg_material(10, PlgDialect::BlackArt).color, vga_palette(10));
}

TEST(Plg, PlxDescriptorBits) {
  // RGB flag, 4.4.4 colour: each nibble n is n / 15.
  Material rgb = plg_material(0x8f80, PlgDialect::Plx);
  EXPECT_EQ(rgb.color, (Vec3{15 / 15.0f, 8 / 15.0f, 0}));
  EXPECT_EQ(rgb.shading, Shading::Unlit);  // shade bits 00: pure (constant), unlit
  EXPECT_FALSE(rgb.two_sided);
  // Shade mode, bits 13-14.
  EXPECT_EQ(plg_material(0xa0f0, PlgDialect::Plx).shading, Shading::Flat);     // 01 flat
  EXPECT_EQ(plg_material(0xc0f0, PlgDialect::Plx).shading, Shading::Gouraud);  // 10 Gouraud
  EXPECT_EQ(plg_material(0xe0f0, PlgDialect::Plx).shading, Shading::Phong);    // 11 Phong
  // Two-sided, bit 12.
  EXPECT_TRUE(plg_material(0xd0f0, PlgDialect::Plx).two_sided);
  EXPECT_FALSE(plg_material(0xc0f0, PlgDialect::Plx).two_sided);
  EXPECT_EQ(plg_material(0xd0f0, PlgDialect::Plx).color, (Vec3{0, 1, 0}));
  EXPECT_EQ(plg_material(0xdfff, PlgDialect::Plx).color, (Vec3{1, 1, 1}));
  // Indexed: 8 bits of palette index, the rest of bits 8-11 ignored.
  Material idx = plg_material(0x4047, PlgDialect::Plx);
  EXPECT_EQ(idx.color, vga_palette(0x47));
  EXPECT_EQ(idx.shading, Shading::Gouraud);
  EXPECT_FALSE(idx.two_sided);
  EXPECT_TRUE(plg_material(0x3037, PlgDialect::Plx).two_sided);
  EXPECT_EQ(plg_material(0x0f47, PlgDialect::Plx).color, vga_palette(0x47));
}

TEST(Plg, DialectComesFromHashCommentsExtensionOrTheRgbFlag) {
  const char* tri = "t 3 1\n0 0 0\n1 0 0\n0 1 0\n0x109f 3 0 1 2\n";
  // Black Art: 0x109f is flat and one-sided.
  const Mesh& black = only_mesh(parse_plg(tri, "t.plg"));
  EXPECT_EQ(black.materials[0].shading, Shading::Flat);
  EXPECT_FALSE(black.materials[0].two_sided);
  // The same descriptor in a PLX file: constant, two-sided.
  EXPECT_TRUE(only_mesh(parse_plg(std::string("# plx\n") + tri, "t.plg")).materials[0].two_sided);
  EXPECT_TRUE(only_mesh(parse_plg(tri, "dir/T.PLX")).materials[0].two_sided);
  const char* rgb = "t 3 2\n0 0 0\n1 0 0\n0 1 0\n0x109f 3 0 1 2\n0x8fff 3 0 1 2\n";
  EXPECT_TRUE(only_mesh(parse_plg(rgb, "t.plg")).materials[0].two_sided);
}

// ---- winding and axes ---------------------------------------------------------------------------

TEST(Plg, BlackArtCubeListedCounterClockwiseOnScreenFacesOutwards) {
  // Black Art's front faces have (v2 - v0) x (v1 - v0) towards the viewer: the reverse of
  // a right-handed counter-clockwise listing.
  Model m = parse_plg(cube_plg(true, "0x109f", ";"), "cube.plg");
  expect_all_faces_outwards(only_mesh(m), "Black Art cube");
}

TEST(Plg, TricksCubeListedClockwiseOnScreenFacesOutwards) {
  // Tricks' front faces have (v1 - v0) x (v2 - v0) towards the viewer.
  Model m = parse_plg(cube_plg(false, "0xd0f0", "#"), "cube.plg");
  expect_all_faces_outwards(only_mesh(m), "Tricks cube");
}

TEST(Plg, LeftHandedZIsNegated) {
  const Mesh& mesh = only_mesh(parse_plg("t 3 1\n1 2 3\n0 0 0\n0 1 0\n10 3 0 1 2\n", "t.plg"));
  EXPECT_EQ(mesh.positions[0], (Vec3{1, 2, -3}));
}

TEST(Plg, RealBlackArtCubeFacesPointOutwards) {
  std::string path = shared_data("models/plg/CUBE.PLG");
  VELOCITY_REQUIRE_SHARED(path);
  Model m = load_plg(path);
  const Mesh& mesh = only_mesh(m);
  EXPECT_EQ(mesh.vertex_count(), 8u);
  EXPECT_EQ(mesh.triangle_count(), 12u);
  expect_all_faces_outwards(mesh, "CUBE.PLG");
  // The top (y = 20) stays on top.
  EXPECT_EQ(mesh.bounds().max.y, 20.0f);
}

TEST(Plg, RealTricksCubeFacesPointOutwards) {
  std::string path = shared_data("models/plg/cube1.plg");
  VELOCITY_REQUIRE_SHARED(path);
  Model m = load_plg(path);
  EXPECT_EQ(m.nodes[0].name, "tri");  // the object's name, not the file's
  const Mesh& mesh = only_mesh(m);
  EXPECT_EQ(mesh.triangle_count(), 12u);
  expect_all_faces_outwards(mesh, "cube1.plg");
  EXPECT_EQ(mesh.materials.at(0).shading, Shading::Gouraud);  // 0xd0f0
  EXPECT_TRUE(mesh.materials.at(0).two_sided);
}

// ---- errors ------------------------------------------------------------------------------------

TEST(Plg, ErrorsNameFileLineAndExpectation) {
  EXPECT_EQ(error_of("cube 3 1\n0 0 0\n1 0 0\n0 1 0\n0x109f 3 0 1 3\n"),
            "t.plg:5: expected vertex number 3 of 3, below 3, got '3'");
  EXPECT_EQ(error_of("cube 3 1\n0 0 0\n1 0\n0 1 0\n"),
            "t.plg:3: expected vertex 1 of 3 as 'x y z' (finite numbers), got '1 0'");
  EXPECT_EQ(error_of("cube 3 1\n0 0 0\n1 0 0\n0 1 0\n0x109f 3 0 1 2 7\n"),
            "t.plg:5: expected the end of the line after 3 vertex numbers, got '7'");
  EXPECT_EQ(error_of("cube 3 1\n0 0 0\n1 0 0\n0 1 0\n0x1109f 3 0 1 2\n"),
            "t.plg:5: expected a 16-bit polygon descriptor (decimal or 0x hex), got '0x1109f'");
  EXPECT_EQ(error_of("cube 3 1\n0 0 0\n1 0 0\n0 1 0\n-5 3 0 1 2\n"),
            "t.plg:5: expected a 16-bit polygon descriptor (decimal or 0x hex), got '-5'");
  EXPECT_EQ(error_of("cube 3 1\n0 0 0\n1 0 0\n0 1 0\n10 0\n"),
            "t.plg:5: expected the polygon's vertex count (1 or more), got '0'");
  EXPECT_EQ(error_of("cube 3 1\n0 0 nan\n"), "t.plg:2: expected vertex 0 of 3 as 'x y z' (finite numbers), got '0 0 nan'");
}

TEST(Plg, CountsAreCheckedAgainstTheData) {
  EXPECT_EQ(error_of("cube 4 1\n0 0 0\n1 0 0\n0 1 0\n"), "t.plg:1: expected 4 vertices (header), got 3");
  EXPECT_EQ(error_of("; c\ncube 3 2\n0 0 0\n1 0 0\n0 1 0\n10 3 0 1 2\n"), "t.plg:2: expected 2 polygons (header), got 1");
  EXPECT_EQ(error_of("cube 3 1\n0 0 0\n1 0 0\n0 1 0\n10 3 0 1 2\n10 3 0 1 2\n"),
            "t.plg:6: expected the end of the file after 1 polygons (header, line 1), got '10 3 0 1 2'");
  EXPECT_EQ(error_of(""), "t.plg:1: expected a PLG header 'name vertex_count polygon_count', got none");
  EXPECT_EQ(error_of("; only comments\n\n"),
            "t.plg:2: expected a PLG header 'name vertex_count polygon_count', got none");
}

TEST(Plg, HugeHeaderCountsAllocateNothingAndFail) {
  std::string e = error_of("x 4000000000 4000000000\n");
  EXPECT_NE(e.find("more than LoadOptions::max_memory allows"), std::string::npos) << e;
  EXPECT_EQ(error_of("x 40000000 1\n0 0 0\n"), "t.plg:1: expected 40000000 vertices (header), got 1");
}

TEST(Plg, HtmlIsRejected) {
  EXPECT_EQ(error_of("<html>\n<body>\n"),
            "t.plg:1: expected a PLG header 'name vertex_count polygon_count' (is this a PLG file?), got '<html>'");
}

TEST(Plg, MsvcBuildLogImpostorIsRejected) {
  std::string path = shared_data("models/plg/invalid/cube.plg");
  VELOCITY_REQUIRE_SHARED(path);
  try {
    load_plg(path);
    FAIL() << "an HTML build log loaded as a PLG model";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("cube.plg:1: expected a PLG header"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("is this a PLG file?"), std::string::npos) << e.what();
  }
}

// ---- truncated and damaged input ----------------------------------------------------------------

void check_every_prefix(const std::string& bytes, const std::string& what) {
  size_t loaded = 0;
  for (size_t n = 0; n <= bytes.size(); ++n)
    loaded += loads_or_throws_error([&] { parse_plg(std::string_view(bytes).substr(0, n), what); },
                                    what + " cut at " + std::to_string(n));
  EXPECT_GT(loaded, 0u) << what;
}

TEST(Plg, EveryPrefixOfAnInlineCubeLoadsOrThrows) { check_every_prefix(cube_plg(true, "0x109f", ";"), "cube"); }

TEST(Plg, EveryPrefixOfRealFilesLoadsOrThrows) {
  for (const char* file : {"models/plg/CUBE.PLG", "models/plg/tank1.plg", "models/plg/CUBE_CH17.PLG"}) {
    std::string path = shared_data(file);
    VELOCITY_REQUIRE_SHARED(path);
    check_every_prefix(read_bytes(path), file);
  }
}

TEST(Plg, DamagedBytesLoadOrThrow) {
  std::string original = cube_plg(false, "0xd0f0", "#") + "# tail\r\n";
  test::Rng rng;
  const char alphabet[] = "0123456789 x;#-.\r\n\t\xff";
  for (int i = 0; i < 3000; ++i) {
    std::string bytes = original;
    for (int e = 1 + int(rng.next() % 4); e > 0; --e) {
      size_t at = rng.next() % bytes.size();
      switch (rng.next() % 3) {
        case 0: bytes[at] = alphabet[rng.next() % (sizeof alphabet - 1)]; break;
        case 1: bytes.erase(at, 1 + rng.next() % 4); break;
        case 2: bytes.insert(at, 1, alphabet[rng.next() % (sizeof alphabet - 1)]); break;
      }
      if (bytes.empty()) bytes.assign(1, 'x');
    }
    loads_or_throws_error([&] { parse_plg(bytes, "damaged.plg"); }, "mutation " + std::to_string(i));
  }
}

}  // namespace
}  // namespace velocity
