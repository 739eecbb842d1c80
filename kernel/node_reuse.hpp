#pragma once
// Skipping the rewrite of a .node: when the input points came from a 0-based .node
// file, that file already is the output's .node (the build keeps every input point,
// in input order), so it is kept (the output path is the input itself) or copied
// byte for byte, at disk speed, instead of formatting the points again.
#include <string>

namespace dtlab {

enum class NodeReuse { none, same_file, copied };

// `input`: a .node file read with numbering base 0. Returns none (nothing written,
// the caller writes the points) when it can no longer be read; a failed write of
// `output` throws InputError as every writer does (kernel/output_file.hpp).
NodeReuse reuse_node_file(const std::string& input, const std::string& output);

}  // namespace dtlab
