#include "kernel/node_reuse.hpp"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <vector>

#include "kernel/output_file.hpp"

namespace dtlab {

NodeReuse reuse_node_file(const std::string& input, const std::string& output) {
  std::error_code ec;
  if (std::filesystem::equivalent(input, output, ec) && !ec) return NodeReuse::same_file;
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> in(std::fopen(input.c_str(), "rb"), &std::fclose);
  if (!in) return NodeReuse::none;
  OutputFile out(output, "wb");
  std::vector<char> buf(std::size_t{4} << 20);
  for (std::size_t got; (got = std::fread(buf.data(), 1, buf.size(), in.get())) > 0;)
    if (std::fwrite(buf.data(), 1, got, out.get()) != got) break;  // out.close() names the error
  // A read error midway: the copy is incomplete, and the output must not claim success.
  if (std::ferror(in.get())) throw InputError(input, 0, "read failed while copying to " + output);
  out.close();
  return NodeReuse::copied;
}

}  // namespace dtlab
