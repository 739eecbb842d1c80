#pragma once
// The samplers of chapter 3 and the robust one, over one mesh. Each call is seeded
// (std::mt19937_64) and reproducible: the same mesh, request and seed give the same
// points whatever the number of threads.
#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "sampling/bvh.hpp"
#include "sampling/signed_distance.hpp"
#include "sampling/winding_number.hpp"

namespace dtlab {

enum class SampleMethod { surface, rays, sdf, winding };

std::optional<SampleMethod> parse_sample_method(std::string_view name);
std::string_view method_name(SampleMethod m);

struct SampleRequest {
  SampleMethod method = SampleMethod::winding;
  std::size_t count = 1000;
  std::uint64_t seed = 1;
  bool blue_noise = false;
  double blue_noise_ratio = 5;  // candidates drawn per kept point before elimination
};

struct SampleOutput {
  std::vector<Point3> points;   // may hold fewer than requested if the budget ran out
  std::size_t candidates = 0;   // box points tried (sdf, winding) or rays shot (rays)
};

class MeshSampler {
 public:
  // Keeps a reference to `mesh`, which must outlive the sampler.
  explicit MeshSampler(const TriangleMesh& mesh);

  SampleOutput sample(const SampleRequest& r) const;

  // area-weighted uniform points on the triangles
  SampleOutput surface(std::size_t count, std::uint64_t seed) const;
  // chapter 3.1: rays between random points on opposite box faces, entry/exit
  // segments by hit parity, length * density samples per segment
  SampleOutput rays(std::size_t count, std::uint64_t seed) const;
  // chapter 3.2: random box points with negative pseudonormal signed distance
  SampleOutput sdf(std::size_t count, std::uint64_t seed) const;
  // random box points with fast winding number above 1/2
  SampleOutput winding(std::size_t count, std::uint64_t seed) const;

  const Bvh& bvh() const { return bvh_; }
  const FastWindingNumber& winding_number() const { return fwn_; }
  const Box3& box() const { return box_; }

 private:
  template <class Inside>
  SampleOutput rejection(std::size_t count, std::uint64_t seed, Inside&& inside) const;

  const TriangleMesh& mesh_;
  Box3 box_;
  Bvh bvh_;
  FastWindingNumber fwn_;
  SignedDistance sdf_;
};

}  // namespace dtlab
