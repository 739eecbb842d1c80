#include "oracle/peers/peer_exchange.hpp"

#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>

namespace dtlab {
namespace {

using File = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

File open_file(const std::string& path, const char* mode) {
  File f(std::fopen(path.c_str(), mode), &std::fclose);
  if (!f) throw std::runtime_error(path + ": cannot open");
  return f;
}

void put(std::FILE* f, const void* data, std::size_t bytes, const std::string& path) {
  if (bytes && std::fwrite(data, 1, bytes, f) != bytes) throw std::runtime_error(path + ": write failed");
}

void get(std::FILE* f, void* data, std::size_t bytes, const std::string& path) {
  if (bytes && std::fread(data, 1, bytes, f) != bytes) throw std::runtime_error(path + ": truncated");
}

std::uint64_t get_count(std::FILE* f, std::size_t item_bytes, const std::string& path) {
  std::uint64_t n = 0;
  get(f, &n, sizeof n, path);
  // Bounded by what is left of the file, so a corrupt count cannot allocate wildly.
  const long here = std::ftell(f);
  std::fseek(f, 0, SEEK_END);
  const long end = std::ftell(f);
  std::fseek(f, here, SEEK_SET);
  if (n > static_cast<std::uint64_t>(end - here) / item_bytes) throw std::runtime_error(path + ": bad count");
  return n;
}

void expect_magic(std::FILE* f, const char* magic, const std::string& path) {
  char m[4];
  get(f, m, 4, path);
  if (std::memcmp(m, magic, 4) != 0) throw std::runtime_error(path + ": not a dtlab peer file");
}

}  // namespace

void write_peer_points(const std::string& path, const std::vector<Point3>& points) {
  File f = open_file(path, "wb");
  const std::uint64_t n = points.size();
  put(f.get(), "DTLP", 4, path);
  put(f.get(), &n, sizeof n, path);
  static_assert(sizeof(Point3) == 3 * sizeof(double));
  put(f.get(), points.data(), n * sizeof(Point3), path);
}

std::vector<Point3> read_peer_points(const std::string& path) {
  File f = open_file(path, "rb");
  expect_magic(f.get(), "DTLP", path);
  std::vector<Point3> points(get_count(f.get(), sizeof(Point3), path));
  get(f.get(), points.data(), points.size() * sizeof(Point3), path);
  return points;
}

void write_peer_answer(const std::string& path, const PeerAnswer& a) {
  File f = open_file(path, "wb");
  put(f.get(), "DTLA", 4, path);
  put(f.get(), &a.seconds, sizeof a.seconds, path);
  const std::uint64_t e = a.extra.size(), t = a.tets.size();
  put(f.get(), &e, sizeof e, path);
  put(f.get(), a.extra.data(), e * sizeof(Point3), path);
  put(f.get(), &t, sizeof t, path);
  static_assert(sizeof(Tet) == 4 * sizeof(std::uint32_t));
  put(f.get(), a.tets.data(), t * sizeof(Tet), path);
  if (std::fflush(f.get()) != 0) throw std::runtime_error(path + ": write failed");
}

PeerAnswer read_peer_answer(const std::string& path) {
  File f = open_file(path, "rb");
  expect_magic(f.get(), "DTLA", path);
  PeerAnswer a;
  get(f.get(), &a.seconds, sizeof a.seconds, path);
  a.extra.resize(get_count(f.get(), sizeof(Point3), path));
  get(f.get(), a.extra.data(), a.extra.size() * sizeof(Point3), path);
  a.tets.resize(get_count(f.get(), sizeof(Tet), path));
  get(f.get(), a.tets.data(), a.tets.size() * sizeof(Tet), path);
  return a;
}

}  // namespace dtlab
