#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>

#include "oracle/peers/peer_programs.hpp"

#if DTLAB_HAVE_QHULL
extern "C" {
#include <libqhull_r/qhull_ra.h>
}
#endif

namespace dtlab {

#if DTLAB_HAVE_QHULL

namespace {

// The first "QHnnnn" line of qhull's error output, else its first line.
std::string qhull_message(const char* text) {
  std::string s(text ? text : "");
  std::size_t at = s.find("QH");
  if (at == std::string::npos) at = 0;
  const std::size_t end = s.find('\n', at);
  return s.substr(at, end == std::string::npos ? std::string::npos : end - at);
}

}  // namespace

PeerAnswer peer_qhull(const std::vector<Point3>& points, bool joggle) {
  std::vector<coordT> coords(points.size() * 3);
  for (std::size_t i = 0; i < points.size(); ++i) {
    coords[3 * i] = points[i].x;
    coords[3 * i + 1] = points[i].y;
    coords[3 * i + 2] = points[i].z;
  }
  char* err_text = nullptr;
  std::size_t err_size = 0;
  std::FILE* err = open_memstream(&err_text, &err_size);
  qhT qh_qh;
  qhT* qh = &qh_qh;
  QHULL_LIB_CHECK
  qh_zero(qh, err);
  char flags[64];
  std::snprintf(flags, sizeof flags, "%s", joggle ? "qhull d QJ" : "qhull d Qbb Qc Qz Q12 Qt");
  PeerAnswer a;
  const auto start = std::chrono::steady_clock::now();
  const int code = qh_new_qhull(qh, 3, static_cast<int>(points.size()), coords.data(), False, flags, nullptr, err);
  a.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::string message;
  if (code == 0) {
    const int n = static_cast<int>(points.size());
    facetT* facet;
    vertexT *vertex, **vertexp;
    FORALLfacets {
      if (facet->upperdelaunay) continue;
      Tet t{};
      int k = 0;
      FOREACHvertex_(facet->vertices) {
        const int id = qh_pointid(qh, vertex->point);
        if (k < 4) t[k] = id >= 0 && id < n ? static_cast<std::uint32_t>(id) : static_cast<std::uint32_t>(n);
        ++k;
      }
      if (k != 4) {
        message = "a lower-Delaunay facet with " + std::to_string(k) + " vertices";
        break;
      }
      a.tets.push_back(t);
    }
    // Any id outside the input (Qz's point at infinity) is the one extra vertex n.
    a.extra.push_back({std::numeric_limits<double>::quiet_NaN(), 0, 0});
  }
  qh_freeqhull(qh, !qh_ALL);
  int curlong = 0, totlong = 0;
  qh_memfreeshort(qh, &curlong, &totlong);
  std::fclose(err);
  if (code != 0) message = qhull_message(err_text);
  std::free(err_text);
  if (!message.empty()) throw PeerRefusal(message);
  return a;
}

std::string qhull_version() { return std::string("qhull ") + qh_version; }

#else

PeerAnswer peer_qhull(const std::vector<Point3>&, bool) {
  throw PeerNotInstalled("built without libqhull_r (Debian libqhull-dev)");
}
std::string qhull_version() { throw PeerNotInstalled("built without libqhull_r (Debian libqhull-dev)"); }

#endif

}  // namespace dtlab
