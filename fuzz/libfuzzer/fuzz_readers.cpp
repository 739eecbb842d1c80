// libFuzzer target: the file readers. Byte 0 picks the format (its value mod 7:
// .node .xyz .ele .off .obj .ply .stl; for .ele, bit 3 picks 1-based ids), the rest is
// the file's content, written to a scratch file and read. Every reader must return a
// result or throw InputError ("file:line: reason"); any other exception, a sanitizer
// report, a huge allocation (libFuzzer's -rss_limit_mb) or a hang is a finding.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "kernel/input_error.hpp"
#include "kernel/point_io.hpp"
#include "kernel/tet_io.hpp"
#include "sampling/mesh_io.hpp"

using namespace dtlab;

namespace {

const char* const kExtensions[] = {".node", ".xyz", ".ele", ".off", ".obj", ".ply", ".stl"};

// The scratch folder, removed at exit (each input file is unlinked after its read).
char g_scratch[] = "/tmp/dtlab_fuzz_readers_XXXXXX";

const std::string& scratch_dir() {
  static const std::string dir = [] {
    if (!mkdtemp(g_scratch)) std::abort();
    std::atexit([] { rmdir(g_scratch); });
    return std::string(g_scratch);
  }();
  return dir;
}

volatile std::size_t g_sink = 0;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const int format = data[0] % 7;
  const std::string path = scratch_dir() + "/in" + kExtensions[format];
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) std::abort();
  if (size > 1) std::fwrite(data + 1, 1, size - 1, f);
  std::fclose(f);
  try {
    switch (format) {
      case 0: g_sink = g_sink + read_node(path).points.size(); break;
      case 1: g_sink = g_sink + read_xyz(path).points.size(); break;
      case 2: g_sink = g_sink + read_ele(path, (data[0] >> 3) & 1, 16).size(); break;
      default: g_sink = g_sink + read_mesh(path).triangles.size(); break;
    }
  } catch (const InputError&) {
    // the promised answer to a bad file
  }
  unlink(path.c_str());
  return 0;
}
