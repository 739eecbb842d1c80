#pragma once
// NumPy .npy files (format version 1.0) of the points and tets, for big runs: no text
// to format or parse, numpy.load reads them directly (and so do meshio users and
// dtlab's Python module, whose arrays have the same dtypes and orientation).
//   PREFIX.points.npy  float64, shape (n, 3), little endian
//   PREFIX.tets.npy    uint32, shape (m, 4), 0-based, dtlab's orientation (orient3d > 0,
//                      as dtlab.tetrahedralize returns them; .ele files swap two vertices)
#include <span>
#include <string>

#include "kernel/tetrahedralization.hpp"

namespace dtlab {

void write_npy_points(const std::string& path, std::span<const Point3> points);
void write_npy_tets(const std::string& path, std::span<const Tet> tets);
// Both files of a tetrahedralization.
void write_npy(const std::string& prefix, const Tetrahedralization& t);

// The 1.0 header of a C-order array (magic, version, length, the dict padded to a
// multiple of 64 bytes), e.g. descr "<f8", shape "(10, 3)".
std::string npy_header(const std::string& descr, const std::string& shape);

}  // namespace dtlab
