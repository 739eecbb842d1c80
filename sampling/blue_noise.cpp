#include "sampling/blue_noise.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

#include "sampling/box3.hpp"

namespace dtlab {

namespace {

// Uniform hash grid: neighbours within `cell` of a point lie in the 27 cells around it.
class Grid {
 public:
  Grid(const std::vector<Point3>& p, double cell) : p_(p), inv_(1.0 / cell) {
    for (std::uint32_t i = 0; i < p.size(); ++i) cells_[key(p[i], 0, 0, 0)].push_back(i);
  }
  template <class F>
  void near(const Point3& q, F&& f) const {
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          auto it = cells_.find(key(q, dx, dy, dz));
          if (it != cells_.end())
            for (std::uint32_t j : it->second) f(j);
        }
  }

 private:
  std::uint64_t key(const Point3& q, int dx, int dy, int dz) const {
    auto c = [&](double v, int d) { return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(v * inv_)) + d) & 0x1fffff; };
    return c(q.x, dx) | c(q.y, dy) << 21 | c(q.z, dz) << 42;
  }
  const std::vector<Point3>& p_;
  double inv_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
};

}  // namespace

std::vector<Point3> eliminate_samples(const std::vector<Point3>& in, std::size_t target, int dim, double measure) {
  const std::size_t m = in.size();
  if (target >= m) return in;
  if (target == 0) return {};
  if (m >= UINT32_MAX) throw std::length_error("eliminate_samples: more than 2^32 candidates");
  // Yuksel's maximal radius for N points: the densest packing of disks (2D) or balls (3D).
  const double n = static_cast<double>(target);
  const double r_max = dim == 2 ? std::sqrt(measure / (2 * std::sqrt(3.0) * n))
                                : std::cbrt(measure / (4 * std::sqrt(2.0) * n));
  // Weight limiting: distances below 2 r_min count as 2 r_min (beta 0.65, gamma 1.5).
  const double r_min = r_max * (1 - std::pow(n / static_cast<double>(m), 1.5)) * 0.65;
  const double reach = 2 * r_max;
  auto weight = [&](double d) { return std::pow(1 - std::max(d, 2 * r_min) / reach, 8); };

  // Neighbour lists (compressed rows) within 2 r_max.
  const Grid grid(in, reach);
  struct Neighbour {
    std::uint32_t id;
    double weight;
  };
  std::vector<std::uint32_t> start(m + 1, 0);
  std::vector<Neighbour> nbr;
  nbr.reserve(16 * m);
  std::vector<double> w(m, 0.0);
  for (std::uint32_t i = 0; i < m; ++i) {
    grid.near(in[i], [&](std::uint32_t j) {
      if (j == i) return;
      const double d = norm(in[i] - in[j]);
      if (d < reach) {
        nbr.push_back({j, weight(d)});
        w[i] += nbr.back().weight;
      }
    });
    start[i + 1] = static_cast<std::uint32_t>(nbr.size());
  }

  // Indexed max-heap on the weights; pos[i] is i's slot, or -1 once removed.
  std::vector<std::uint32_t> heap(m);
  std::vector<std::int64_t> pos(m);
  for (std::uint32_t i = 0; i < m; ++i) heap[i] = i, pos[i] = i;
  auto above = [&](std::uint32_t a, std::uint32_t b) { return w[a] > w[b] || (w[a] == w[b] && a < b); };
  auto place = [&](std::size_t s, std::uint32_t v) { heap[s] = v, pos[v] = static_cast<std::int64_t>(s); };
  std::size_t size = m;
  auto sift_down = [&](std::size_t s) {
    const std::uint32_t v = heap[s];
    for (;;) {
      std::size_t c = 2 * s + 1;
      if (c >= size) break;
      if (c + 1 < size && above(heap[c + 1], heap[c])) ++c;
      if (!above(heap[c], v)) break;
      place(s, heap[c]);
      s = c;
    }
    place(s, v);
  };
  for (std::size_t s = m / 2; s-- > 0;) sift_down(s);

  while (size > target) {
    const std::uint32_t top = heap[0];
    pos[top] = -1;
    --size;
    if (size > 0) {
      place(0, heap[size]);
      sift_down(0);
    }
    // Removing `top` lightens its neighbours; weights only drop, so they sift down.
    for (std::uint32_t k = start[top]; k < start[top + 1]; ++k) {
      const std::uint32_t j = nbr[k].id;
      if (pos[j] < 0) continue;
      w[j] -= nbr[k].weight;
      sift_down(static_cast<std::size_t>(pos[j]));
    }
  }
  std::vector<Point3> out;
  out.reserve(target);
  for (std::uint32_t i = 0; i < m; ++i)
    if (pos[i] >= 0) out.push_back(in[i]);
  return out;
}

double min_pair_distance(const std::vector<Point3>& p) {
  if (p.size() < 2) return INFINITY;
  Box3 box;
  for (const Point3& q : p) box.add(q);
  const Point3 e = box.extent();
  const double vol = std::max({e.x * e.y * e.z, 1e-300});
  // Start with a cell of about one point's share of the box and grow until a pair is found.
  double cell = std::max(std::cbrt(vol / static_cast<double>(p.size())), 1e-12 * std::max({e.x, e.y, e.z, 1e-300}));
  for (;;) {
    const Grid grid(p, cell);
    double best = INFINITY;
    for (std::uint32_t i = 0; i < p.size(); ++i)
      grid.near(p[i], [&](std::uint32_t j) {
        if (j > i) best = std::min(best, norm(p[i] - p[j]));
      });
    if (best <= cell) return best;  // any closer pair would share or touch a cell
    cell *= 2;
  }
}

}  // namespace dtlab
