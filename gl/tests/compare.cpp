// Compares a conformance program's output from Velocity with Mesa's: every frame
// (NAME.ppm) by PSNR over RGB, which must reach the threshold, and values.txt line by
// line (names equal, numbers within 1e-4 relative). Prints one line per frame:
//   [conformance] PROGRAM FRAME PSNR
// Usage: velocity_gl_compare PROGRAM VELOCITY_DIR MESA_DIR MIN_PSNR
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Ppm {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
};

bool read_ppm(const std::filesystem::path& path, Ppm& out) {
  std::ifstream f(path, std::ios::binary);
  std::string magic;
  int maxval = 0;
  if (!(f >> magic >> out.width >> out.height >> maxval) || magic != "P6" || maxval != 255 || out.width <= 0 ||
      out.height <= 0 || out.width > 16384 || out.height > 16384)
    return false;
  f.get();
  out.rgb.resize(size_t(out.width) * out.height * 3);
  return bool(f.read(reinterpret_cast<char*>(out.rgb.data()), std::streamsize(out.rgb.size())));
}

double psnr(const Ppm& a, const Ppm& b) {
  double se = 0;
  for (size_t i = 0; i < a.rgb.size(); ++i) {
    const double d = double(a.rgb[i]) - double(b.rgb[i]);
    se += d * d;
  }
  if (se == 0) return 99.0;
  return 10.0 * std::log10(255.0 * 255.0 / (se / double(a.rgb.size())));
}

std::vector<std::string> lines(const std::filesystem::path& p) {
  std::ifstream f(p);
  std::vector<std::string> out;
  for (std::string l; std::getline(f, l);)
    if (!l.empty()) out.push_back(l);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::cerr << "usage: velocity_gl_compare PROGRAM VELOCITY_DIR MESA_DIR MIN_PSNR\n";
    return 2;
  }
  const std::string program = argv[1];
  const std::filesystem::path ours = argv[2], mesa = argv[3];
  const double min_psnr = std::atof(argv[4]);
  int failures = 0, frames = 0;
  std::vector<std::filesystem::path> names;
  for (const auto& e : std::filesystem::directory_iterator(mesa))
    if (e.path().extension() == ".ppm") names.push_back(e.path().filename());
  std::sort(names.begin(), names.end());
  for (const auto& name : names) {
    Ppm a, b;
    if (!read_ppm(mesa / name, b)) {
      std::cerr << program << ": Mesa's " << name << " is unreadable\n";
      ++failures;
      continue;
    }
    if (!read_ppm(ours / name, a)) {
      std::cerr << program << ": Velocity wrote no readable " << name << "\n";
      ++failures;
      continue;
    }
    if (a.width != b.width || a.height != b.height) {
      std::cerr << program << ": " << name << " sizes differ\n";
      ++failures;
      continue;
    }
    ++frames;
    const double p = psnr(a, b);
    std::printf("[conformance] %s %s %.1f\n", program.c_str(), name.stem().c_str(), p);
    if (p < min_psnr) {
      std::fprintf(stderr, "%s: frame %s PSNR %.2f dB < %.1f\n", program.c_str(), name.stem().c_str(), p, min_psnr);
      ++failures;
    }
  }
  const auto va = lines(ours / "values.txt"), vb = lines(mesa / "values.txt");
  if (va.size() != vb.size()) {
    std::cerr << program << ": " << va.size() << " values from Velocity, " << vb.size() << " from Mesa\n";
    ++failures;
  }
  for (size_t i = 0; i < std::min(va.size(), vb.size()); ++i) {
    std::istringstream sa(va[i]), sb(vb[i]);
    std::string na, nb;
    double xa = 0, xb = 0;
    sa >> na >> xa, sb >> nb >> xb;
    const bool same = na == nb && std::fabs(xa - xb) <= 1e-4 * std::max(1.0, std::fabs(xb));
    std::printf("[value] %s %s velocity=%g mesa=%g%s\n", program.c_str(), na.c_str(), xa, xb, same ? "" : "  DIFFERENT");
    if (!same) ++failures;
  }
  if (frames == 0 && vb.empty()) {
    std::cerr << program << ": Mesa's run produced nothing to compare\n";
    ++failures;
  }
  return failures ? 1 : 0;
}
