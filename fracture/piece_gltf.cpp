#include "fracture/piece_gltf.hpp"

#include <algorithm>
#include <cstring>

#include "kernel/output_file.hpp"
#include "kernel/vtu_writer.hpp"

namespace dtlab {

namespace {
constexpr int kFloat = 5126, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

// The binary buffer and the JSON arrays that index into it.
struct GltfBuilder {
  std::string bytes;
  nlohmann::json views = nlohmann::json::array(), accessors = nlohmann::json::array();

  // Appends raw values as a buffer view; returns its index.
  std::size_t view(const void* data, std::size_t size, int target) {
    while (bytes.size() % 4) bytes.push_back('\0');
    views.push_back({{"buffer", 0}, {"byteOffset", bytes.size()}, {"byteLength", size}, {"target", target}});
    bytes.append(static_cast<const char*>(data), size);
    return views.size() - 1;
  }
  std::size_t positions(const TriangleMesh& m) {
    std::vector<float> xyz;
    std::array<float, 3> lo{}, hi{};
    for (std::size_t i = 0; i < m.vertices.size(); ++i) {
      const std::array<float, 3> p{static_cast<float>(m.vertices[i].x), static_cast<float>(m.vertices[i].y),
                                   static_cast<float>(m.vertices[i].z)};
      for (int k = 0; k < 3; ++k) {
        lo[k] = i ? std::min(lo[k], p[k]) : p[k];
        hi[k] = i ? std::max(hi[k], p[k]) : p[k];
        xyz.push_back(p[k]);
      }
    }
    const auto v = view(xyz.data(), xyz.size() * sizeof(float), kArrayBuffer);
    accessors.push_back({{"bufferView", v}, {"componentType", kFloat}, {"count", m.vertices.size()},
                         {"type", "VEC3"}, {"min", lo}, {"max", hi}});
    return accessors.size() - 1;
  }
  std::size_t indices(const std::vector<std::uint32_t>& ids) {
    const auto v = view(ids.data(), ids.size() * sizeof(std::uint32_t), kElementArrayBuffer);
    accessors.push_back({{"bufferView", v}, {"componentType", kUnsignedInt}, {"count", ids.size()}, {"type", "SCALAR"}});
    return accessors.size() - 1;
  }
};

nlohmann::json material(const char* name, double r, double g, double b) {
  return {{"name", name},
          {"pbrMetallicRoughness", {{"baseColorFactor", {r, g, b, 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.8}}}};
}

// Piece i's mesh: a primitive per material that has triangles.
nlohmann::json piece_mesh(GltfBuilder& b, std::size_t i, const Piece& p) {
  const std::size_t pos = b.positions(p.geometry.mesh);
  nlohmann::json prims = nlohmann::json::array();
  for (int cut = 0; cut < 2; ++cut) {
    std::vector<std::uint32_t> ids;
    for (std::size_t t = 0; t < p.geometry.mesh.triangles.size(); ++t)
      if ((p.geometry.cut[t] != 0) == (cut != 0))
        ids.insert(ids.end(), p.geometry.mesh.triangles[t].begin(), p.geometry.mesh.triangles[t].end());
    if (ids.empty()) continue;
    prims.push_back({{"attributes", {{"POSITION", pos}}}, {"indices", b.indices(ids)}, {"material", cut}, {"mode", 4}});
  }
  return {{"name", "piece_" + std::to_string(i)}, {"primitives", std::move(prims)}};
}
}  // namespace

nlohmann::json pieces_gltf(const FractureResult& r) {
  GltfBuilder b;
  nlohmann::json meshes = nlohmann::json::array(), nodes = nlohmann::json::array(), roots = nlohmann::json::array();
  for (std::size_t i = 0; i < r.pieces.size(); ++i) {
    meshes.push_back(piece_mesh(b, i, r.pieces[i]));
    const Piece& p = r.pieces[i];
    nodes.push_back({{"name", "piece_" + std::to_string(i)}, {"mesh", i},
                     {"extras", {{"volume", p.volume}, {"site_index", p.site_index}, {"island", p.island}}}});
    roots.push_back(i);
  }
  nlohmann::json g;
  g["asset"] = {{"version", "2.0"}, {"generator", "dtlab fracture"}};
  g["scene"] = 0;
  g["scenes"] = nlohmann::json::array({{{"nodes", roots}}});
  g["nodes"] = std::move(nodes);
  g["meshes"] = std::move(meshes);
  g["materials"] = nlohmann::json::array({material("outer", 0.70, 0.72, 0.78), material("cut", 0.85, 0.35, 0.20)});
  g["accessors"] = std::move(b.accessors);
  g["bufferViews"] = std::move(b.views);
  g["buffers"] = nlohmann::json::array(
      {{{"byteLength", b.bytes.size()},
        {"uri", "data:application/octet-stream;base64," + base64_encode(b.bytes.data(), b.bytes.size())}}});
  return g;
}

void write_pieces_gltf(const std::string& path, const FractureResult& r) {
  write_text_file(path, pieces_gltf(r).dump() + "\n");
}

}  // namespace dtlab
