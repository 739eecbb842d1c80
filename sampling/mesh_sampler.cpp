#include "sampling/mesh_sampler.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include "sampling/blue_noise.hpp"
#include "sampling/mesh_magnitude.hpp"
#include "sampling/morton_order.hpp"

namespace dtlab {

std::optional<SampleMethod> parse_sample_method(std::string_view name) {
  if (name == "surface") return SampleMethod::surface;
  if (name == "rays") return SampleMethod::rays;
  if (name == "sdf") return SampleMethod::sdf;
  if (name == "winding") return SampleMethod::winding;
  return std::nullopt;
}

std::string_view method_name(SampleMethod m) {
  switch (m) {
    case SampleMethod::surface: return "surface";
    case SampleMethod::rays: return "rays";
    case SampleMethod::sdf: return "sdf";
    case SampleMethod::winding: return "winding";
  }
  return "?";
}

MeshSampler::MeshSampler(const TriangleMesh& mesh)
    : mesh_(mesh), box_(bounding_box(mesh)), bvh_(mesh), fwn_(bvh_), sdf_(bvh_) {}

SampleOutput MeshSampler::sample(const SampleRequest& r) const {
  // Python's sample and fracture's sites come here too: one rule for the magnitudes.
  const MeshMagnitude mag = measure_magnitude(mesh_, surface_area(mesh_), signed_volume(mesh_));
  if (const std::string why = magnitude_problem(mag, r.method == SampleMethod::surface); !why.empty())
    throw std::invalid_argument(why);
  const std::size_t n = r.blue_noise ? static_cast<std::size_t>(std::ceil(r.count * r.blue_noise_ratio)) : r.count;
  SampleOutput out;
  switch (r.method) {
    case SampleMethod::surface: out = surface(n, r.seed); break;
    case SampleMethod::rays: out = rays(n, r.seed); break;
    case SampleMethod::sdf: out = sdf(n, r.seed); break;
    case SampleMethod::winding: out = winding(n, r.seed); break;
  }
  if (r.blue_noise && out.points.size() > r.count) {
    // The sampling domain's measure sets the Poisson-disk radius: area for surface
    // points, volume for the others (the mesh's, or the box's when that is not usable).
    const bool surf = r.method == SampleMethod::surface;
    double measure = surf ? surface_area(mesh_) : std::abs(signed_volume(mesh_));
    if (!(measure > 0)) measure = surf ? box_.half_area() * 2 : box_.volume();
    out.points = eliminate_samples(out.points, r.count, surf ? 2 : 3, measure);
  }
  return out;
}

SampleOutput MeshSampler::surface(std::size_t count, std::uint64_t seed) const {
  SampleOutput out;
  const std::size_t nt = mesh_.triangles.size();
  std::vector<double> cdf(nt);
  double total = 0;
  for (std::size_t t = 0; t < nt; ++t) cdf[t] = total += mesh_.triangle_area(t);
  if (!(total > 0)) return out;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  out.points.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double pick = U(rng) * total;
    const std::size_t t = std::min<std::size_t>(std::upper_bound(cdf.begin(), cdf.end(), pick) - cdf.begin(), nt - 1);
    // Chapter 3's barycentric method: u + v <= 1 by folding the unit square.
    double u = U(rng), v = U(rng);
    if (u + v > 1) u = 1 - u, v = 1 - v;
    const Point3& a = mesh_.corner(t, 0);
    out.points.push_back(a + u * (mesh_.corner(t, 1) - a) + v * (mesh_.corner(t, 2) - a));
  }
  out.candidates = count;
  return out;
}

SampleOutput MeshSampler::rays(std::size_t count, std::uint64_t seed) const {
  SampleOutput out;
  if (box_.empty() || count == 0) return out;
  const Point3 e = box_.extent();
  // Linear density: samples per unit length, the spacing `count` points would have
  // filling the box; a segment of length L gets L * density samples.
  const double vol = box_.volume();
  if (!(vol > 0)) return out;  // a flat mesh encloses nothing
  const double density = std::cbrt(static_cast<double>(count) / vol);
  // Pick the pair of opposite faces in proportion to their area, so the ray ends are
  // uniform on the box surface.
  const double fa[3] = {e.y * e.z, e.z * e.x, e.x * e.y};
  const double fsum = fa[0] + fa[1] + fa[2];
  if (!(fsum > 0)) return out;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<double> hits;
  const std::size_t max_rays = 100 * count + 10000;
  auto on_face = [&](int axis, bool high) {
    Point3 p{box_.lo.x + U(rng) * e.x, box_.lo.y + U(rng) * e.y, box_.lo.z + U(rng) * e.z};
    const double v = high ? coord(box_.hi, axis) : coord(box_.lo, axis);
    (axis == 0 ? p.x : axis == 1 ? p.y : p.z) = v;
    return p;
  };
  while (out.points.size() < count && out.candidates < max_rays) {
    // A mesh enclosing (almost) nothing would otherwise spin through the whole budget.
    if (out.candidates >= 100000 && out.points.size() * 10000 < out.candidates) break;
    ++out.candidates;
    const double f = U(rng) * fsum;
    const int axis = f < fa[0] ? 0 : (f < fa[0] + fa[1] ? 1 : 2);
    const Point3 o = on_face(axis, false), end = on_face(axis, true);
    const Point3 d = end - o;
    hits.clear();
    bvh_.for_each_ray_hit(o, d, 1.0, [&](std::uint32_t, double t) { hits.push_back(t); });
    std::sort(hits.begin(), hits.end());
    const double len = norm(d);
    // Entry/exit pairs by parity; an odd hit left over has no exit and is dropped.
    for (std::size_t k = 0; k + 1 < hits.size() && out.points.size() < count; k += 2) {
      const double t0 = hits[k], t1 = hits[k + 1];
      const double want = std::min((t1 - t0) * len * density, static_cast<double>(count));
      std::size_t n = static_cast<std::size_t>(want);
      if (U(rng) < want - n) ++n;  // stochastic rounding keeps the expected count exact
      for (std::size_t s = 0; s < n && out.points.size() < count; ++s) out.points.push_back(o + (t0 + U(rng) * (t1 - t0)) * d);
    }
  }
  return out;
}

template <class Inside>
SampleOutput MeshSampler::rejection(std::size_t count, std::uint64_t seed, Inside&& inside) const {
  SampleOutput out;
  if (box_.empty() || count == 0 || !(box_.volume() > 0)) return out;  // flat: encloses nothing
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const Point3 e = box_.extent();
  const double fill = std::clamp(std::abs(signed_volume(mesh_)) / box_.volume(), 0.01, 1.0);
  const std::size_t max_candidates = 1000 * count + 100000;
  std::vector<Point3> batch;
  std::vector<char> keep;
  while (out.points.size() < count && out.candidates < max_candidates) {
    // A mesh enclosing (almost) nothing would otherwise spin through the whole budget.
    if (out.candidates >= 1000000 && out.points.size() * 10000 < out.candidates) break;
    // Batch size depends on counts only, never on threads: results stay reproducible.
    const std::size_t want = count - out.points.size();
    const std::size_t n = std::clamp<std::size_t>(static_cast<std::size_t>(1.2 * want / fill) + 64, 1024, 1 << 22);
    batch.resize(n);
    for (Point3& p : batch) p = {box_.lo.x + U(rng) * e.x, box_.lo.y + U(rng) * e.y, box_.lo.z + U(rng) * e.z};
    keep = classify_points(batch, box_, inside);
    for (std::size_t i = 0; i < n && out.points.size() < count; ++i) {
      ++out.candidates;
      if (keep[i]) out.points.push_back(batch[i]);
    }
  }
  return out;
}

SampleOutput MeshSampler::sdf(std::size_t count, std::uint64_t seed) const {
  return rejection(count, seed, [this](const Point3& p) { return sdf_(p) < 0; });
}

SampleOutput MeshSampler::winding(std::size_t count, std::uint64_t seed) const {
  return rejection(count, seed, [this](const Point3& p) { return fwn_.inside(p); });
}

}  // namespace dtlab
