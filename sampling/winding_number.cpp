#include "sampling/winding_number.hpp"

#include <array>
#include <cmath>
#include <numbers>

#include "sampling/morton_order.hpp"

namespace dtlab {

double winding_number_exact(const TriangleMesh& mesh, const Point3& q) {
  double w = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    w += triangle_winding(q, mesh.corner(t, 0), mesh.corner(t, 1), mesh.corner(t, 2));
  return w;
}

FastWindingNumber::FastWindingNumber(const Bvh& bvh, double beta, int expansion_order)
    : bvh_(bvh), beta2_(beta * beta), beta_(beta), order_(expansion_order) {
  const auto& nodes = bvh.nodes();
  const auto& order = bvh.order();
  const TriangleMesh& mesh = bvh.mesh();
  corners_.reserve(3 * order.size());
  for (std::uint32_t t : order)
    for (int k = 0; k < 3; ++k) corners_.push_back(mesh.corner(t, k));
  // Children follow their parent in the array, so a backward sweep sees them first.
  // Each node covers a contiguous range [begin, end) of the leaf order.
  const std::size_t nn = nodes.size();
  std::vector<std::uint32_t> begin(nn), end(nn);
  std::vector<double> area(nn, 0.0);
  std::vector<Point3> moment(nn, Point3{0, 0, 0}), normal(nn, Point3{0, 0, 0});
  for (std::size_t i = nn; i-- > 0;) {
    const BvhNode& n = nodes[i];
    if (n.leaf()) {
      begin[i] = n.first;
      end[i] = n.first + n.count;
      for (std::uint32_t k = begin[i]; k < end[i]; ++k) {
        const std::uint32_t t = order[k];
        const double a = mesh.triangle_area(t);
        area[i] += a;
        moment[i] += (a / 3) * (mesh.corner(t, 0) + mesh.corner(t, 1) + mesh.corner(t, 2));
        normal[i] += 0.5 * mesh.area_normal(t);
      }
    } else {
      const std::size_t l = i + 1, r = n.right;
      begin[i] = begin[l];
      end[i] = end[r];
      area[i] = area[l] + area[r];
      moment[i] = moment[l] + moment[r];
      normal[i] = normal[l] + normal[r];
    }
  }
  // First-order moments M = sum_i A_i n_i (c_i - center)^T, bottom-up: shifting a
  // child's expansion to the parent's centre adds N_child (c_child - center)^T.
  std::vector<Point3> center(nn);
  std::vector<std::array<double, 9>> m(nn);
  for (std::size_t i = nn; i-- > 0;) {
    const BvhNode& n = nodes[i];
    center[i] = area[i] > 0 ? (1.0 / area[i]) * moment[i] : n.box.center();
    auto add_outer = [&](const Point3& a, const Point3& d, std::array<double, 9>& out) {
      const double av[3] = {a.x, a.y, a.z}, dv[3] = {d.x, d.y, d.z};
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) out[3 * r + c] += av[r] * dv[c];
    };
    m[i].fill(0);
    if (n.leaf()) {
      for (std::uint32_t k = begin[i]; k < end[i]; ++k) {
        const std::uint32_t t = order[k];
        const Point3 c = (1.0 / 3) * (mesh.corner(t, 0) + mesh.corner(t, 1) + mesh.corner(t, 2));
        add_outer(0.5 * mesh.area_normal(t), c - center[i], m[i]);
      }
    } else {
      for (std::size_t ch : {i + 1, static_cast<std::size_t>(n.right)}) {
        for (int k = 0; k < 9; ++k) m[i][k] += m[ch][k];
        add_outer(normal[ch], center[ch] - center[i], m[i]);
      }
    }
  }
  far_.resize(nn);
  for (std::size_t i = 0; i < nn; ++i) {
    double r2 = 0;
    for (std::size_t k = 3 * begin[i]; k < 3 * end[i]; ++k) r2 = std::max(r2, norm2(corners_[k] - center[i]));
    FarField& f = far_[i];
    f = FarField{};
    f.link = nodes[i].leaf() ? nodes[i].first : nodes[i].right;
    f.count = nodes[i].count;
    f.center[0] = static_cast<float>(center[i].x);
    f.center[1] = static_cast<float>(center[i].y);
    f.center[2] = static_cast<float>(center[i].z);
    // Rounded up so that the far-field test stays conservative.
    f.radius2 = static_cast<float>(r2 * (1 + 1e-6)) + 1e-30f;
    f.normal[0] = static_cast<float>(normal[i].x);
    f.normal[1] = static_cast<float>(normal[i].y);
    f.normal[2] = static_cast<float>(normal[i].z);
    const auto& a = m[i];
    f.trace = static_cast<float>(a[0] + a[4] + a[8]);
    // Only the symmetric part of M enters r^T M r.
    f.m[0] = static_cast<float>(a[0]);
    f.m[1] = static_cast<float>(a[4]);
    f.m[2] = static_cast<float>(a[8]);
    f.m[3] = static_cast<float>(a[1] + a[3]);
    f.m[4] = static_cast<float>(a[5] + a[7]);
    f.m[5] = static_cast<float>(a[6] + a[2]);
  }
}

double FastWindingNumber::operator()(const Point3& q) const {
  if (far_.empty()) return 0;
  constexpr double inv4pi = 0.25 / std::numbers::pi;
  double far = 0, near = 0;
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const std::uint32_t i = stack[--top];
    const FarField& f = far_[i];
    const double rx = f.center[0] - q.x, ry = f.center[1] - q.y, rz = f.center[2] - q.z;
    const double r2 = rx * rx + ry * ry + rz * rz;
    if (r2 > beta2_ * f.radius2) {
      // Field of a unit dipole density: g(x) = (x - q) / (4 pi |x - q|^3). Summing
      // A_i n_i . g(c_i) expanded around center (r = center - q) gives
      //   N . r / |r|^3 + (tr M) / |r|^3 - 3 r^T M r / |r|^5, all over 4 pi.
      const double inv_r2 = 1.0 / r2, inv_r3 = inv_r2 * std::sqrt(inv_r2);
      double v = f.normal[0] * rx + f.normal[1] * ry + f.normal[2] * rz;
      if (order_ > 0) {
        const double rmr = f.m[0] * rx * rx + f.m[1] * ry * ry + f.m[2] * rz * rz + f.m[3] * rx * ry +
                           f.m[4] * ry * rz + f.m[5] * rz * rx;
        v += f.trace - 3 * rmr * inv_r2;
      }
      far += v * inv_r3;
      continue;
    }
    if (f.count > 0) {
      const Point3* c = corners_.data() + 3 * f.link;
      double s = 0;
      for (std::uint32_t k = 0; k < f.count; ++k, c += 3) s += triangle_winding(q, c[0], c[1], c[2]);
      near += s;
    } else {
      stack[top++] = f.link;
      stack[top++] = i + 1;
    }
  }
  return near + inv4pi * far;
}

std::vector<char> inside_flags(const FastWindingNumber& w, const std::vector<Point3>& q) {
  return classify_points(q, bounding_box(w.mesh()), [&w](const Point3& p) { return w.inside(p); });
}

std::vector<char> inside_flags_robust(const Bvh& bvh, const std::vector<Point3>& q, double margin) {
  const FastWindingNumber strict(bvh, 4.0);
  return classify_points(q, bounding_box(bvh.mesh()), [&](const Point3& p) {
    double w = strict(p);
    if (std::abs(std::abs(w) - 0.5) < margin) w = winding_number_exact(bvh.mesh(), p);
    return std::abs(w) > 0.5;
  }, 128);
}

}  // namespace dtlab
