#include "programs/circuit.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace velocity::realtime {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// The layout, in metres (x, z), in the direction of travel; the start line is on the
// first stretch. A long straight, a fast sweeper, an S, a hairpin, a loop round the hill.
constexpr float kLayout[][2] = {
    {150, 150},   {150, -50},   {138, -150},  {90, -210},   {20, -205},   {-20, -150}, {-60, -100},
    {-140, -130}, {-220, -165}, {-265, -100}, {-250, 0},    {-195, 60},   {-120, 55},  {-60, 100},
    {-45, 190},   {10, 250},    {100, 245},   {145, 205}};
constexpr size_t kLayoutPoints = sizeof kLayout / sizeof kLayout[0];

Vec3 layout(size_t i) {
  const float* p = kLayout[i % kLayoutPoints];
  return {p[0], 0, p[1]};
}

Vec3 catmull_rom(Vec3 p0, Vec3 p1, Vec3 p2, Vec3 p3, float t) {
  float t2 = t * t, t3 = t2 * t;
  return (p1 * 2.0f + (p2 - p0) * t + (p0 * 2.0f - p1 * 5.0f + p2 * 4.0f - p3) * t2 + (p1 * 3.0f - p0 - p2 * 3.0f + p3) * t3) *
         0.5f;
}

float smoothstep(float a, float b, float x) {
  float t = std::clamp((x - a) / (b - a), 0.0f, 1.0f);
  return t * t * (3 - 2 * t);
}

// A closed sequence averaged over +-radius neighbours, `passes` times.
void smooth_closed(std::vector<float>& v, int radius, int passes) {
  const int n = int(v.size());
  std::vector<float> out(v.size());
  for (int pass = 0; pass < passes; ++pass) {
    for (int i = 0; i < n; ++i) {
      float sum = 0;
      for (int k = -radius; k <= radius; ++k) sum += v[size_t(((i + k) % n + n) % n)];
      out[size_t(i)] = sum / float(2 * radius + 1);
    }
    v.swap(out);
  }
}

float heading_of(Vec3 t) { return std::atan2(-t.x, -t.z); }

}  // namespace

float hills(float x, float z) {
  return 7.0f * std::sin(x * 0.011f + 0.5f) * std::cos(z * 0.009f) + 3.0f * std::sin(x * 0.023f - z * 0.017f + 1.3f);
}

Circuit::Circuit() {
  build_line();
  build_racing_line();
  build_ground();
}

void Circuit::build_line() {
  // The spline, densely, with its running length.
  std::vector<Vec3> dense;
  std::vector<float> run;
  const int per = 200;
  float total = 0;
  for (size_t i = 0; i < kLayoutPoints; ++i)
    for (int k = 0; k < per; ++k) {
      Vec3 p = catmull_rom(layout(i + kLayoutPoints - 1), layout(i), layout(i + 1), layout(i + 2), float(k) / per);
      if (!dense.empty()) total += velocity::length(p - dense.back());
      dense.push_back(p);
      run.push_back(total);
    }
  total += velocity::length(dense.front() - dense.back());
  // Resampled evenly.
  const size_t n = size_t(std::lround(total / kSampleStep));
  const float step = total / float(n);
  length_ = total;
  samples_.resize(n);
  size_t j = 0;
  for (size_t i = 0; i < n; ++i) {
    float s = step * float(i);
    while (j + 1 < dense.size() && run[j + 1] < s) ++j;
    Vec3 a = dense[j], b = j + 1 < dense.size() ? dense[j + 1] : dense.front();
    float span = (j + 1 < dense.size() ? run[j + 1] : total) - run[j];
    samples_[i].centre = a + (b - a) * (span > 0 ? (s - run[j]) / span : 0.0f);
    samples_[i].s = s;
  }
  // Directions, curvature (heading change a metre), height and banking.
  std::vector<float> curvature(n), height(n);
  for (size_t i = 0; i < n; ++i) {
    Vec3 t = normalize(samples_[(i + 1) % n].centre - samples_[(i + n - 1) % n].centre);
    samples_[i].tangent = t;
    samples_[i].right = {-t.z, 0, t.x};
    height[i] = hills(samples_[i].centre.x, samples_[i].centre.z);
  }
  for (size_t i = 0; i < n; ++i) {
    float a = heading_of(samples_[(i + n - 1) % n].tangent), b = heading_of(samples_[(i + 1) % n].tangent);
    curvature[i] = std::remainder(b - a, 2 * kPi) / (2 * step);
  }
  smooth_closed(curvature, 4, 2);
  smooth_closed(height, 12, 3);  // gentle gradients: the hills smoothed along the road
  std::vector<float> bank(n);
  for (size_t i = 0; i < n; ++i) bank[i] = std::clamp(curvature[i] * 6.0f, -0.1f, 0.1f);
  smooth_closed(bank, 3, 2);
  for (size_t i = 0; i < n; ++i) {
    samples_[i].curvature = curvature[i];
    samples_[i].centre.y = height[i];
    samples_[i].bank = bank[i];
  }
}

void Circuit::build_racing_line() {
  // Towards the inside of each bend, from the curvature over a longer stretch; the
  // fastest speed from the grip a car has left for cornering, then braking distances
  // carried back from each slow corner (twice round, for the corners near the line).
  const size_t n = samples_.size();
  std::vector<float> wide(n), line(n), fast(n);
  for (size_t i = 0; i < n; ++i) wide[i] = samples_[i].curvature;
  smooth_closed(wide, 8, 2);
  for (size_t i = 0; i < n; ++i) line[i] = std::clamp(-wide[i] * 160.0f, -3.5f, 3.5f);
  smooth_closed(line, 4, 2);
  const float corner = 0.75f * 0.95f * 9.81f, brake = 6.0f, top = 48.0f;
  for (size_t i = 0; i < n; ++i) {
    float k = std::max(std::abs(samples_[i].curvature), 1e-4f);
    fast[i] = std::min(top, std::sqrt(corner / k));
  }
  const float step = length_ / float(n);
  for (int round = 0; round < 2; ++round)
    for (size_t k = n; k-- > 0;) {
      float next = fast[(k + 1) % n];
      fast[k] = std::min(fast[k], std::sqrt(next * next + 2 * brake * step));
    }
  for (size_t i = 0; i < n; ++i) samples_[i].line = line[i], samples_[i].top_speed = fast[i];
}

void Circuit::build_ground() {
  // Each grid vertex: under the road, a little below it; beside it, a verge at the road
  // edge's height blending into the hills over 40 m (the road is cut into them).
  cells_ = int(2 * kGroundHalf / kGroundCell);
  ground_.assign(size_t(cells_ + 1) * size_t(cells_ + 1), 0.0f);
  for (int iz = 0; iz <= cells_; ++iz)
    for (int ix = 0; ix <= cells_; ++ix) {
      float x = -kGroundHalf + float(ix) * kGroundCell, z = -kGroundHalf + float(iz) * kGroundCell;
      TrackPosition t = locate({x, 0, z});
      const float edge_lat = kHalfWidth + kKerbWidth;
      float beyond = t.distance - edge_lat;
      TrackPosition edge = t;
      edge.lateral = std::clamp(t.lateral, -edge_lat, edge_lat);
      float h;
      if (beyond < 0) h = road_height(t) - 0.5f;
      else h = road_height(edge) - 0.12f + (hills(x, z) - road_height(edge) + 0.12f) * smoothstep(6, 40, beyond);
      ground_[size_t(iz) * size_t(cells_ + 1) + size_t(ix)] = h;
    }
}

Circuit::Sample Circuit::at(float s) const {
  const size_t n = samples_.size();
  s = std::fmod(std::fmod(s, length_) + length_, length_);
  float f = s / length_ * float(n);
  size_t i = std::min(size_t(f), n - 1);
  float t = f - float(i);
  const Sample &a = samples_[i], &b = samples_[(i + 1) % n];
  Sample r = a;
  r.s = s;
  r.centre = a.centre + (b.centre - a.centre) * t;
  r.tangent = normalize(a.tangent + (b.tangent - a.tangent) * t);
  r.right = {-r.tangent.z, 0, r.tangent.x};
  r.curvature = a.curvature + (b.curvature - a.curvature) * t;
  r.bank = a.bank + (b.bank - a.bank) * t;
  r.line = a.line + (b.line - a.line) * t;
  r.top_speed = a.top_speed + (b.top_speed - a.top_speed) * t;
  return r;
}

Vec3 Circuit::point(float s, float lateral) const {
  Sample a = at(s);
  return a.centre + a.right * lateral + Vec3{0, a.bank * lateral, 0};
}

Vec3 Circuit::tangent(float s) const { return at(s).tangent; }

TrackPosition Circuit::locate(Vec3 p, const TrackPosition* hint) const {
  const size_t n = samples_.size();
  auto search = [&](long from, long to, TrackPosition& best) {
    float best_d2 = 1e30f;
    for (long k = from; k <= to; ++k) {
      size_t i = size_t(((k % long(n)) + long(n)) % long(n));
      const Sample &a = samples_[i], &b = samples_[(i + 1) % n];
      float ex = b.centre.x - a.centre.x, ez = b.centre.z - a.centre.z;
      float px = p.x - a.centre.x, pz = p.z - a.centre.z;
      float len2 = ex * ex + ez * ez;
      float t = len2 > 0 ? std::clamp((px * ex + pz * ez) / len2, 0.0f, 1.0f) : 0.0f;
      float dx = px - ex * t, dz = pz - ez * t;
      float d2 = dx * dx + dz * dz;
      if (d2 < best_d2) {
        best_d2 = d2;
        Vec3 right = normalize(a.right + (b.right - a.right) * t);
        best.index = i;
        best.s = a.s + t * (length_ / float(n));
        best.lateral = dx * right.x + dz * right.z;
        best.distance = std::sqrt(d2);
      }
    }
    return best_d2;
  };
  TrackPosition r;
  if (hint) {
    const long window = 10;
    search(long(hint->index) - window, long(hint->index) + window, r);
    long off = long(r.index) - long(hint->index);
    off = ((off % long(n)) + long(n) + long(n) / 2) % long(n) - long(n) / 2;
    if (std::abs(off) < window) return r;  // not at the window's edge: the nearest
  }
  search(0, long(n) - 1, r);
  return r;
}

float Circuit::road_height(const TrackPosition& t) const {
  const size_t n = samples_.size();
  const Sample &a = samples_[t.index], &b = samples_[(t.index + 1) % n];
  float f = std::clamp((t.s - a.s) / (length_ / float(n)), 0.0f, 1.0f);
  float y = a.centre.y + (b.centre.y - a.centre.y) * f;
  float bank = a.bank + (b.bank - a.bank) * f;
  return y + bank * t.lateral;
}

float Circuit::ground_height(float x, float z) const {
  float fx = std::clamp((x + kGroundHalf) / kGroundCell, 0.0f, float(cells_) - 1e-3f);
  float fz = std::clamp((z + kGroundHalf) / kGroundCell, 0.0f, float(cells_) - 1e-3f);
  int ix = int(fx), iz = int(fz);
  float u = fx - float(ix), w = fz - float(iz);
  float h00 = ground_vertex(ix, iz), h10 = ground_vertex(ix + 1, iz), h01 = ground_vertex(ix, iz + 1),
        h11 = ground_vertex(ix + 1, iz + 1);
  // The cell's two triangles split along its (0,0)-(1,1) diagonal, as drawn.
  if (u >= w) return h00 + u * (h10 - h00) + w * (h11 - h10);
  return h00 + w * (h01 - h00) + u * (h11 - h01);
}

float Circuit::height(float x, float z, const TrackPosition* hint, TrackPosition* where) const {
  TrackPosition t = locate({x, 0, z}, hint);
  if (where) *where = t;
  return on_road(t) ? road_height(t) : ground_height(x, z);
}

bool Circuit::kerbed(size_t i) const { return std::abs(samples_[i % samples_.size()].curvature) > 1.0f / 110.0f; }

float Circuit::closest_approach() const {
  const size_t n = samples_.size();
  const size_t apart = size_t(150.0f / (length_ / float(n)));
  float best = 1e30f;
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + apart; j + apart < n + i && j < n; ++j) {
      Vec3 d = samples_[i].centre - samples_[j].centre;
      best = std::min(best, std::sqrt(d.x * d.x + d.z * d.z));
    }
  return best;
}

}  // namespace velocity::realtime
