// .ele reading: the plain-file fast path and the strict reader agree. Every variant
// below holds the same two tets; the fast path takes only the first, the strict
// reader the others, and both must return the same tets (or the strict reader's error).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "kernel/input_error.hpp"
#include "kernel/tet_io.hpp"

using namespace dtlab;
namespace fs = std::filesystem;

namespace {
std::string write_ele(const std::string& name, const std::string& text) {
  fs::path dir = fs::temp_directory_path() / "dtlab_tests_tet_io";
  fs::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary) << text;
  return (dir / name).string();
}
std::string error_of(const std::string& path, int first, std::size_t points) {
  try {
    read_ele(path, first, points);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
// path + suffix by append (GCC 12's -Wrestrict misfires on operator+ chains here).
std::string at(std::string path, const char* suffix) { return path.append(suffix); }
}  // namespace

TEST_CASE(".ele variants read to the same tets, first vertices swapped into dtlab's orientation") {
  const std::vector<Tet> expected = {{1, 0, 2, 3}, {2, 1, 3, 4}};
  const char* variants[] = {
      "2 4 0\n0 0 1 2 3\n1 1 2 3 4\n",            // plain: the fast path
      "2 4 0\n0 0 1 2 3\n1 1 2 3 4\n\n  \n",      // trailing blank lines
      "2\n0 0 1 2 3\n1 1 2 3 4\n",                // header without the optional fields
      "2 4 0\r\n0 0 1 2 3\r\n1 1 2 3 4\r\n",      // CRLF
      "# comment\n2 4 0\n0 0 1 2 3 # c\n\n1 1 2 3 4\n",
      "2 4 0\n0, 0, 1, 2, 3\n1 +1 2 3 4\n",       // commas, a plus sign
      "2 4 0\n0 0 1 2 3\n1 1 2 3 4",              // no final newline
      "2 4 1\n0 0 1 2 3 7\n1 1 2 3 4 8\n",        // an attribute
      "2 4 0\nx 0 1 2 3\n1 1 2 3 4\n",            // the tet's own index is not read
      "2 4 0\n0 000000000000000000000 1 2 3\n1 1 2 3 4\n",  // 21 digits, value 0
  };
  int i = 0;
  for (const char* text : variants) {
    INFO("variant " << i);
    std::string name = std::to_string(i++);
    CHECK(read_ele(write_ele(name.append(".ele"), text), 0, 5) == expected);
  }
  // 1-based ids.
  CHECK(read_ele(write_ele("one.ele", "2 4 0\n1 1 2 3 4\n2 2 3 4 5\n"), 1, 5) == expected);
}

TEST_CASE(".ele errors come from the strict reader, with file and line") {
  const std::string range = write_ele("range.ele", "2 4 0\n0 0 1 2 3\n1 1 2 3 5\n");
  CHECK(error_of(range, 0, 5) == at(range, ":3: vertex index 5 out of range"));
  const std::string short_file = write_ele("short.ele", "3 4 0\n0 0 1 2 3\n1 1 2 3 4\n          \n");
  CHECK(error_of(short_file, 0, 5) == at(short_file, ":4: expected 3 tetrahedra, file ends after 2"));
  const std::string extra = write_ele("extra.ele", "1 4 0\n0 0 1 2 3\n1 1 2 3 4\n");
  CHECK(error_of(extra, 0, 5) == at(extra, ":3: unexpected data after the last tetrahedron (the header says 1)"));
  const std::string fields = write_ele("fields.ele", "1 4 0\n0 0 1 2\n");
  CHECK(error_of(fields, 0, 5) == at(fields, ":2: expected 5 fields, got 4"));
  const std::string zero = write_ele("zero_based.ele", "1 4 0\n0 0 1 2 3\n");
  CHECK(error_of(zero, 1, 5) == at(zero, ":2: vertex index 0 out of range"));
}
