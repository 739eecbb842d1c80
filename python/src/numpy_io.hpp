#pragma once
// numpy arrays in and out of the library's types.
//
// In: an (n, 3) float64 C-contiguous array is viewed as Point3s without a copy (Point3
// is three packed doubles); other real arrays and nested sequences are converted once.
// Every coordinate must be finite. Index arrays of any integer dtype are range-checked.
// Out: a std::vector is moved into a capsule that owns it and numpy views its storage.
// Wrong shapes, NaNs and out-of-range indices raise ValueError.
#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "predicates/point.hpp"

namespace dtlab::python {

static_assert(sizeof(Point3) == 3 * sizeof(double) && alignof(Point3) == alignof(double));

using DoubleArray = pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>;

// `obj` as an (n, 3) finite float64 array (a view of `obj` itself when it already is
// one). Keep the returned array alive while using points_of(array).
DoubleArray point_array(pybind11::handle obj, const char* what);
std::span<const Point3> points_of(const DoubleArray& a);

// An (m, K) integer array with every entry in [0, limit), copied into rows.
template <std::size_t K>
std::vector<std::array<std::uint32_t, K>> index_rows(pybind11::handle obj, std::size_t limit, const char* what);

// A 1-D integer array with every entry in [0, limit).
std::vector<std::uint32_t> index_list(pybind11::handle obj, std::size_t limit, const char* what);

// Moves `v` into numpy: shape (v.size(), K) of Scalar, where each element of v is K
// packed Scalars (Point3 -> float64 (n, 3), Tet -> uint32 (m, 4), scalars -> (n,)).
template <class Scalar, std::size_t K, class T>
pybind11::array_t<Scalar> to_numpy(std::vector<T>&& v) {
  static_assert(sizeof(T) == K * sizeof(Scalar));
  auto* owner = new std::vector<T>(std::move(v));
  pybind11::capsule base(owner, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  const auto n = static_cast<pybind11::ssize_t>(owner->size());
  const Scalar* data = owner->empty() ? nullptr : reinterpret_cast<const Scalar*>(owner->data());
  if constexpr (K == 1)
    return pybind11::array_t<Scalar>({n}, data, base);
  else
    return pybind11::array_t<Scalar>({n, static_cast<pybind11::ssize_t>(K)}, data, base);
}

inline pybind11::array_t<double> points_to_numpy(std::vector<Point3>&& v) {
  return to_numpy<double, 3>(std::move(v));
}

// A read-only view of `count` rows of K Scalars at `data`, kept alive by `owner`.
template <class Scalar, std::size_t K>
pybind11::array_t<Scalar> readonly_view(const void* data, std::size_t count, pybind11::handle owner) {
  const auto n = static_cast<pybind11::ssize_t>(count);
  pybind11::array_t<Scalar> a =
      K == 1 ? pybind11::array_t<Scalar>({n}, static_cast<const Scalar*>(data), owner)
             : pybind11::array_t<Scalar>({n, static_cast<pybind11::ssize_t>(K)}, static_cast<const Scalar*>(data), owner);
  a.attr("setflags")(pybind11::arg("write") = false);
  return a;
}

}  // namespace dtlab::python
