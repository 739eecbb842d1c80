// dtlab_fuzz_reproduce CRASH_FILE OUT.node: turns a crash of dtlab_fuzz_insertion into
// a corpus-style input. Decodes the bytes as the target does, reruns the build with
// adaptive+sos, exact+sos and exact (the outcome of each is printed: a failure of
// exact+sos too points at the kernel or the checker, of adaptive+sos alone at the
// predicates), shrinks the points by ddmin while adaptive+sos keeps failing, and
// writes them as a .node file for `dtlab fuzz --replay OUT.node`.
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <vector>

#include "fuzz/libfuzzer/byte_points.hpp"
#include "fuzz/outcome.hpp"
#include "fuzz/shrink.hpp"
#include "kernel/point_io.hpp"

using namespace dtlab;

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s CRASH_FILE OUT.node\n", argv[0]);
    return 2;
  }
  std::ifstream in(argv[1], std::ios::binary);
  const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), {}};
  auto pts = fuzz::decode_points(bytes, 64);
  if (pts.empty()) {
    std::fprintf(stderr, "no points in %s\n", argv[1]);
    return 2;
  }
  BuildOptions options;
  options.seed = 1 + bytes[0] / 4;
  const PredicateSpec adaptive_sos{"adaptive", 1e-12, false, true};
  for (const PredicateSpec& spec :
       {adaptive_sos, PredicateSpec{"exact", 1e-12, false, true}, PredicateSpec{"exact", 1e-12, false, false}}) {
    const fuzz::CaseRun run = fuzz::run_case(pts, spec, options);
    std::printf("%-13s %s %s\n", fuzz::backend_label(spec).c_str(), run.outcome.c_str(),
                run.detail.c_str());
  }
  const auto fails = [&](const std::vector<Point3>& p) {
    return !fuzz::run_case(p, adaptive_sos, options).ok();
  };
  if (fails(pts)) {
    const fuzz::ShrinkResult shrunk = fuzz::shrink_points(pts, fails);
    std::printf("shrunk %zu -> %zu points (%zu builds%s)\n", pts.size(), shrunk.points.size(),
                shrunk.tests, shrunk.minimal ? ", 1-minimal" : "");
    pts = shrunk.points;
  }
  write_node(argv[2], pts);
  std::printf("wrote %s (BRIO seed %llu)\n", argv[2], static_cast<unsigned long long>(options.seed));
  return 0;
}
