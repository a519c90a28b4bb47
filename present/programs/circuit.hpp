// The driving game's circuit: a closed road over hilly ground, as data the race and the
// scene share. The centre line is a closed Catmull-Rom spline through hand-placed points,
// resampled every kSampleStep metres; the road's height follows the hills (smoothed
// along the road), and it banks into the bends. The ground is a height field whose
// triangles are the ones drawn, so a wheel sits exactly on what the player sees.
#pragma once

#include <cstddef>
#include <vector>

#include "velocity/math.hpp"

namespace velocity::realtime {

// Where a point is relative to the road.
struct TrackPosition {
  size_t index = 0;    // the centre-line sample at the start of the segment it is beside
  float s = 0;         // metres along the centre line from the start line
  float lateral = 0;   // metres to the right of the centre line (negative: left)
  float distance = 0;  // metres from the centre line (|lateral| where beside a segment)
};

class Circuit {
 public:
  static constexpr float kHalfWidth = 6.0f;    // the road, edge to centre
  static constexpr float kKerbWidth = 1.2f;    // kerbs outside the edges in the bends
  static constexpr float kSampleStep = 4.0f;   // metres between centre-line samples
  static constexpr float kGroundCell = 10.0f;  // the height field's grid
  static constexpr float kGroundHalf = 450.0f; // the ground spans +-this in x and z
  static constexpr int kCheckpoints = 10;      // gate 0 is the start and finish line

  struct Sample {
    Vec3 centre;        // on the road surface
    Vec3 tangent;       // unit, horizontal, the direction of travel
    Vec3 right;         // unit, horizontal
    float s = 0;        // metres from the start line
    float curvature = 0;  // 1 / radius, positive turning left, smoothed
    float bank = 0;     // height gained a metre to the right (the outside of a left bend rises)
    float line = 0;     // the racing line's lateral offset (metres, positive right)
    float top_speed = 0;  // the fastest the racing line can be taken here (m/s), braking included
  };

  Circuit();

  float length() const { return length_; }
  const std::vector<Sample>& samples() const { return samples_; }
  // A point `s` metres along (wrapping), `lateral` metres to the right, on the road surface.
  Vec3 point(float s, float lateral = 0) const;
  // The direction of travel at `s`.
  Vec3 tangent(float s) const;
  Sample at(float s) const;  // interpolated between samples
  // Where `p` is (x and z only): searched near `hint` when given (the last answer for
  // something that moves a little each step), else along the whole line.
  TrackPosition locate(Vec3 p, const TrackPosition* hint = nullptr) const;
  // True where the surface is the road (kerbs included), false on the grass.
  bool on_road(const TrackPosition& t) const { return std::abs(t.lateral) <= kHalfWidth + kKerbWidth; }
  // The ground's height under (x, z): the road's surface on the road, the height field's
  // triangles elsewhere. `hint` as for locate; `where` receives the track position.
  float height(float x, float z, const TrackPosition* hint = nullptr, TrackPosition* where = nullptr) const;
  // The height field's height (the drawn ground triangles, the road ignored).
  float ground_height(float x, float z) const;
  // Grid vertex heights, (cells + 1)^2, row by row along +z then +x within a row.
  int ground_cells() const { return cells_; }
  float ground_vertex(int ix, int iz) const { return ground_[size_t(iz) * size_t(cells_ + 1) + size_t(ix)]; }
  // The checkpoint gates' distances along the line.
  float checkpoint(int k) const { return length_ * float(k) / float(kCheckpoints); }
  // Whether the bend at sample i is tight enough for kerbs.
  bool kerbed(size_t i) const;
  // The smallest distance between two stretches of centre line at least 150 m apart along
  // it (the layout's sanity: the road never runs into itself).
  float closest_approach() const;

 private:
  void build_line();
  void build_racing_line();
  void build_ground();
  float road_height(const TrackPosition& t) const;

  std::vector<Sample> samples_;
  float length_ = 0;
  int cells_ = 0;
  std::vector<float> ground_;
};

// The hills before the road is cut into them (metres).
float hills(float x, float z);

}  // namespace velocity::realtime
