#include "python/src/numpy_io.hpp"

#include <cstdint>
#include <cmath>
#include <sstream>

namespace py = pybind11;

namespace dtlab::python {
namespace {

std::string shape_text(const py::array& a) {
  std::ostringstream o;
  o << '(';
  for (py::ssize_t i = 0; i < a.ndim(); ++i) o << (i ? ", " : "") << a.shape(i);
  o << (a.ndim() == 1 ? ",)" : ")");
  return o.str();
}

// `obj` as a numpy array of integers (no copy when it already is one).
py::array integer_array(py::handle obj, const char* what) {
  py::array a = py::array::ensure(obj);
  if (!a) throw py::value_error(std::string(what) + " must be an integer array");
  if (a.size() == 0 && a.dtype().kind() == 'f') a = a.attr("astype")("int64");  // np.empty((0, 4))
  const char kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u')
    throw py::value_error(std::string(what) + " must be an integer array, got dtype " +
                          py::str(a.dtype()).cast<std::string>());
  // uint64 beyond int64 would wrap to a negative index in the message: named as given.
  if (kind == 'u' && a.dtype().itemsize() == 8 && a.size() > 0) {
    const py::object top = a.attr("max")();
    if (top.attr("__gt__")(py::int_(INT64_MAX)).cast<bool>())
      throw py::value_error(std::string(what) + ": vertex index " + py::str(top).cast<std::string>() +
                            " out of range");
  }
  return a;
}

// The bits of an unsigned integer array, 0 for a signed one: a subtraction that went
// below 0 wraps there (numpy's uint32 tets - 100 holds 4294967237), which the message says.
int unsigned_bits(const py::array& a) {
  return a.dtype().kind() == 'u' ? static_cast<int>(8 * a.dtype().itemsize()) : 0;
}

void check_index(std::int64_t v, std::size_t limit, const char* what, std::size_t row, std::size_t col, bool matrix,
                 int unsigned_width) {
  if (v < 0 || static_cast<std::uint64_t>(v) >= limit) {
    std::ostringstream o;
    o << what << '[' << row;
    if (matrix) o << ", " << col;
    o << "]: vertex index " << v << " out of range (" << limit << " points)";
    if (unsigned_width >= 8 && unsigned_width <= 32 && static_cast<std::uint64_t>(v) >= (1ull << (unsigned_width - 1)))
      o << " (a uint" << unsigned_width << " array: " << (v - (std::int64_t{1} << unsigned_width))
        << " wrapped around)";
    throw py::value_error(o.str());
  }
}

}  // namespace

DoubleArray point_array(py::handle obj, const char* what) {
  py::array raw = py::array::ensure(obj);
  if (!raw) throw py::value_error(std::string(what) + " must be an (n, 3) array of numbers");
  const char kind = raw.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw py::value_error(std::string(what) + " must be an (n, 3) array of real numbers, got dtype " +
                          py::str(raw.dtype()).cast<std::string>());
  if (raw.ndim() != 2 || raw.shape(1) != 3)
    throw py::value_error(std::string(what) + " must be an (n, 3) array, got shape " + shape_text(raw));
  DoubleArray a = DoubleArray::ensure(raw);  // a view when raw is float64 and C-contiguous
  if (!a) throw py::error_already_set();
  const double* d = a.data();
  const std::size_t count = static_cast<std::size_t>(a.size());
  for (std::size_t i = 0; i < count; ++i)
    if (!std::isfinite(d[i])) {
      std::ostringstream o;
      o.precision(17);
      o << what << '[' << i / 3 << "]: non-finite coordinate: " << d[i];
      throw py::value_error(o.str());
    }
  return a;
}

std::span<const Point3> points_of(const DoubleArray& a) {
  return {reinterpret_cast<const Point3*>(a.data()), static_cast<std::size_t>(a.shape(0))};
}

template <std::size_t K>
std::vector<std::array<std::uint32_t, K>> index_rows(py::handle obj, std::size_t limit, const char* what) {
  py::array raw = integer_array(obj, what);
  if (raw.ndim() != 2 || raw.shape(1) != static_cast<py::ssize_t>(K))
    throw py::value_error(std::string(what) + " must be an (m, " + std::to_string(K) + ") array, got shape " +
                          shape_text(raw));
  using I64 = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;
  const I64 a = I64::ensure(raw);
  if (!a) throw py::error_already_set();
  const std::int64_t* d = a.data();
  const std::size_t m = static_cast<std::size_t>(a.shape(0));
  const int width = unsigned_bits(raw);
  std::vector<std::array<std::uint32_t, K>> rows(m);
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t k = 0; k < K; ++k) {
      const std::int64_t v = d[i * K + k];
      check_index(v, limit, what, i, k, true, width);
      rows[i][k] = static_cast<std::uint32_t>(v);
    }
  return rows;
}

template std::vector<std::array<std::uint32_t, 3>> index_rows<3>(py::handle, std::size_t, const char*);
template std::vector<std::array<std::uint32_t, 4>> index_rows<4>(py::handle, std::size_t, const char*);

std::vector<std::uint32_t> index_list(py::handle obj, std::size_t limit, const char* what) {
  py::array raw = integer_array(obj, what);
  if (raw.ndim() != 1)
    throw py::value_error(std::string(what) + " must be a 1-D array, got shape " + shape_text(raw));
  using I64 = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;
  const I64 a = I64::ensure(raw);
  if (!a) throw py::error_already_set();
  const int width = unsigned_bits(raw);
  std::vector<std::uint32_t> out(static_cast<std::size_t>(a.size()));
  for (std::size_t i = 0; i < out.size(); ++i) {
    check_index(a.data()[i], limit, what, i, 0, false, width);
    out[i] = static_cast<std::uint32_t>(a.data()[i]);
  }
  return out;
}

}  // namespace dtlab::python
