#include "families.hpp"

namespace dtlab::test {

// Per family, n inputs (or the full grid), at the natural scale and rescaled by
// 2^500, 2^+-160 (just outside the range of stages A..D), 2^-500 and 2^-1060
// (integers become subnormals).
std::vector<Quad> hard_orient_inputs(std::uint64_t seed, int n) {
  std::mt19937_64 rng(seed);
  std::vector<Quad> base;
  for (int i = 0; i < n; ++i) {  // coplanar pushed through a rounded affine map
    const Quad q = coplanar_int_quad(rng);
    const Affine f = random_affine(rng);
    base.push_back({f(q[0]), f(q[1]), f(q[2]), f(q[3])});
  }
  for (int i = 0; i < n; ++i) {  // collinear triple plus a fourth point
    const Point3 p = small_int_point(rng, 50), u = small_int_point(rng, 20);
    const Affine f = random_affine(rng);
    auto on = [&](double s) { return f(Point3{p.x + s * u.x, p.y + s * u.y, p.z + s * u.z}); };
    base.push_back({on(-1), on(0.5), on(3), f(small_int_point(rng, 50))});
  }
  for (int i = 0; i < n; ++i) {  // exactly coplanar, one coordinate moved by <= 3 ulps
    Quad q = coplanar_int_quad(rng);
    const Point3 o = small_int_point(rng, 1 << 20);
    for (Point3& p : q) p = {p.x + o.x / 7.0, p.y + o.y / 3.0, p.z + o.z};
    q[3] = ulp_nudge(q[3], rng);
    base.push_back(q);
  }
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 16; ++j)
      for (int k = 0; k < 4; ++k) {
        Quad q = kKettnerPlane;
        q[3] = kettner_point(i, j, k);
        base.push_back(q);
      }
  std::vector<Quad> out = base;
  for (int s : {500, 160, -160, -500, -1060}) {
    std::vector<Quad> copy = base;
    for (Quad& q : copy)
      for (Point3& p : q) p = scaled(p, s);
    out.insert(out.end(), copy.begin(), copy.end());
  }
  return out;
}

std::vector<Quint> hard_insphere_inputs(std::uint64_t seed, int n) {
  std::mt19937_64 rng(seed);
  std::vector<Quint> base;
  for (int i = 0; i < n; ++i) {  // cospherical pushed through a rounded similarity
    const Quint q = cospherical_int_quint(rng);
    const Affine f = random_similarity(rng);
    base.push_back({f(q[0]), f(q[1]), f(q[2]), f(q[3]), f(q[4])});
  }
  for (int i = 0; i < n; ++i) {  // exactly cospherical, one coordinate moved by <= 3 ulps
    Quint q = cospherical_int_quint(rng);
    std::uniform_int_distribution<int> w(0, 4);
    const int k = w(rng);
    q[k] = ulp_nudge(q[k], rng);
    base.push_back(q);
  }
  for (int i = 0; i < n; ++i) {  // exactly cospherical, untouched (answer 0)
    base.push_back(cospherical_int_quint(rng));
  }
  for (int i = 0; i < n; ++i) {  // coplanar a,b,c,d (affine image) and any e
    const Quad q = coplanar_int_quad(rng);
    const Affine f = random_affine(rng);
    base.push_back({f(q[0]), f(q[1]), f(q[2]), f(q[3]), f(small_int_point(rng, 50))});
  }
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 16; ++j)
      for (int k = 0; k < 4; ++k) {
        const Quad& s = kKettnerSphere;
        base.push_back({s[0], s[1], s[2], s[3], kettner_point(i, j, k)});
      }
  std::vector<Quint> out = base;
  for (int s : {500, 160, -160, -500, -1060}) {
    std::vector<Quint> copy = base;
    for (Quint& q : copy)
      for (Point3& p : q) p = scaled(p, s);
    out.insert(out.end(), copy.begin(), copy.end());
  }
  return out;
}

}  // namespace dtlab::test
