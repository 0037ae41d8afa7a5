// Mesh files through Assimp: STL ASCII and binary, OBJ, PLY and gzip give the same triangles;
// bad files give one-line errors naming the file.
#include <gtest/gtest.h>
#include <zlib.h>

#include <fmt/format.h>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/world/mesh_hull.hpp"

namespace hullinspect::world {
namespace {

namespace fs = std::filesystem;

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

// A closed unit-ish box (12 facets) as vertices and faces; coordinates exact in float.
const std::vector<std::array<float, 3>> kVertices = {{0, -1, 0}, {4, -1, 0}, {4, 1, 0}, {0, 1, 0},
                                                     {0, -1, 2}, {4, -1, 2}, {4, 1, 2}, {0, 1, 2}};
const std::vector<std::array<int, 3>> kFaces = {{0, 1, 5}, {0, 5, 4}, {3, 7, 6}, {3, 6, 2},
                                                {4, 5, 6}, {4, 6, 7}, {0, 3, 2}, {0, 2, 1},
                                                {0, 4, 7}, {0, 7, 3}, {1, 2, 6}, {1, 6, 5}};

std::string ascii_stl() {
  std::string s = "solid box\n";
  for (const auto& f : kFaces) {
    s += " facet normal 0 0 0\n  outer loop\n";
    for (int i : f) {
      const auto& v = kVertices[static_cast<std::size_t>(i)];
      s += fmt::format("   vertex {} {} {}\n", v[0], v[1], v[2]);
    }
    s += "  endloop\n endfacet\n";
  }
  return s + "endsolid box\n";
}

std::string binary_stl() {
  std::string s(80, ' ');
  const auto put = [&](const void* p, std::size_t n) { s.append(static_cast<const char*>(p), n); };
  const std::uint32_t count = static_cast<std::uint32_t>(kFaces.size());
  put(&count, 4);
  for (const auto& f : kFaces) {
    const float normal[3] = {0, 0, 0};
    put(normal, 12);
    for (int i : f) put(kVertices[static_cast<std::size_t>(i)].data(), 12);
    const std::uint16_t attributes = 0;
    put(&attributes, 2);
  }
  return s;
}

std::string obj() {
  std::string s = "# box\n";
  for (const auto& v : kVertices) s += fmt::format("v {} {} {}\n", v[0], v[1], v[2]);
  for (const auto& f : kFaces) s += fmt::format("f {} {} {}\n", f[0] + 1, f[1] + 1, f[2] + 1);
  return s;
}

std::string ply() {
  std::string s = fmt::format(
      "ply\nformat ascii 1.0\nelement vertex {}\nproperty float x\nproperty float y\n"
      "property float z\nelement face {}\nproperty list uchar int vertex_indices\nend_header\n",
      kVertices.size(), kFaces.size());
  for (const auto& v : kVertices) s += fmt::format("{} {} {}\n", v[0], v[1], v[2]);
  for (const auto& f : kFaces) s += fmt::format("3 {} {} {}\n", f[0], f[1], f[2]);
  return s;
}

std::string gzip(const std::string& bytes) {
  z_stream z{};
  EXPECT_EQ(deflateInit2(&z, 6, Z_DEFLATED, 16 + MAX_WBITS, 8, Z_DEFAULT_STRATEGY), Z_OK);
  std::string out(deflateBound(&z, bytes.size()) + 32, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  z.avail_in = static_cast<uInt>(bytes.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  EXPECT_EQ(deflate(&z, Z_FINISH), Z_STREAM_END);
  out.resize(z.total_out);
  deflateEnd(&z);
  return out;
}

/// The triangles in a canonical order (rotated so the smallest vertex is first, then sorted),
/// so files that list the same facets differently compare equal.
std::vector<MeshTriangle> canonical(std::vector<MeshTriangle> t) {
  for (auto& tri : t) {
    const auto first = std::min_element(tri.v.begin(), tri.v.end()) - tri.v.begin();
    std::rotate(tri.v.begin(), tri.v.begin() + first, tri.v.end());
  }
  std::sort(t.begin(), t.end(), [](const auto& a, const auto& b) { return a.v < b.v; });
  return t;
}

class MeshFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           fmt::format("hullinspect_mesh_{}_{}", ::getpid(),
                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& bytes) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
  }
  fs::path dir_;
};

TEST_F(MeshFiles, EveryFormatGivesTheSameTriangles) {
  const auto expected = canonical(read_mesh(ascii_stl(), "stl", "a.stl"));
  ASSERT_EQ(expected.size(), kFaces.size());
  EXPECT_EQ(canonical(read_mesh(binary_stl(), "stl", "b.stl")), expected);
  EXPECT_EQ(canonical(read_mesh(obj(), "obj", "c.obj")), expected);
  EXPECT_EQ(canonical(read_mesh(ply(), "ply", "d.ply")), expected);
  EXPECT_EQ(canonical(read_mesh(gzip(ascii_stl()), "stl", "e.stl.gz")), expected);
}

TEST_F(MeshFiles, EveryFileImportsToTheSameHull) {
  const std::string reference =
      to_hull_json(import_mesh_file(write("box.stl", ascii_stl()), {}).hull);
  const auto same = [&](const std::string& name, const std::string& bytes) {
    std::string json = to_hull_json(import_mesh_file(write(name, bytes), {}).hull);
    const std::string other = (dir_ / name).string(), mine = (dir_ / "box.stl").string();
    json.replace(json.find(other), other.size(), mine);  // only the mesh name differs
    EXPECT_EQ(json, reference) << name;
  };
  same("bin.stl", binary_stl());
  same("box.OBJ", obj());
  same("box.ply", ply());
  same("box.stl.gz", gzip(ascii_stl()));
  EXPECT_EQ(load_hull(dir_ / "box.ply").cell_count(), 32);
  EXPECT_TRUE(is_mesh_path("a/b.STL.GZ"));
  EXPECT_FALSE(is_mesh_path("a/b.gz"));
  EXPECT_FALSE(is_mesh_path("mask.txt"));
}

TEST_F(MeshFiles, BadFilesAreOneLineErrors) {
  const auto import = [&](const std::string& name, const std::string& bytes) {
    const fs::path p = write(name, bytes);
    std::string e = error_of([&] { import_mesh_file(p, {}); });
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
    const std::string prefix = p.string() + ": ";
    EXPECT_EQ(e.rfind(prefix, 0), 0u) << e;
    return e.substr(std::min(e.size(), prefix.size()));
  };
  EXPECT_EQ(import("empty.stl", ""), "the mesh file is empty");
  EXPECT_EQ(import("bad.stl.gz", "\x1f\x8b garbage"), "corrupt gzip data");
  EXPECT_EQ(import("cut.stl.gz", gzip(ascii_stl()).substr(0, 40)), "truncated gzip data");
  EXPECT_EQ(import("junk.ply", "not a ply at all").rfind("not a readable ply mesh (", 0), 0u);
  EXPECT_EQ(import("lines.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n").rfind("not a readable obj mesh", 0),
            0u);
  EXPECT_EQ(
      error_of([] { import_mesh_file("/nonexistent/x.stl", {}); }).rfind("/nonexistent/x.stl: ", 0),
      0u);
}

// Assimp 5.2 crashes on this PLY body (a vertex element with only x, found by mutating box.ply)
// and never returns from the other two (a list count of 39999999999; a header without
// end_header, which read_mesh refuses before Assimp sees it, so detail:: reaches Assimp
// directly). Assimp runs in a child process: each is a one-line error of the file and this
// process goes on.
const std::string kCrashingPly =
    "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nelement face 12\n"
    "property list uchar int vertex_indices\nend_header\n4 -1 2";
const std::string kHangingPly =
    "ply\nformat ascii 1.0\nelement vertex 8\nelement face 12\n"
    "property list uchar int vertex_indices\nend_header\n0 -1 2\n4 -1 2\n4 1 2\n0 1 2\n"
    "3 0 1 5\n3 0 5 4\n3 3 7 6\n3 3 6 2\n39999999999 4 5 6";

TEST_F(MeshFiles, AssimpCrashesAndHangsAreOneLineErrors) {
  // Both files end before their headers' counts, so read_mesh refuses them before Assimp; the
  // child that runs Assimp is tested on them directly.
  EXPECT_EQ(error_of([&] { import_mesh_file(write("crash.ply", kCrashingPly), {}); }),
            (dir_ / "crash.ply").string() +
                ": not a readable ply mesh (element vertex: 8 declared, but the data ends after 1 "
                "line: truncated?)");
  EXPECT_EQ(error_of([&] {
              detail::read_mesh_in_child(kCrashingPly, "ply", "crash.ply",
                                         std::chrono::seconds(60));
            }),
            "crash.ply: not a readable ply mesh (the mesh reader crashed: signal 11)");
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(error_of([&] { read_mesh(kHangingPly, "ply", "hang.ply", std::chrono::seconds(1)); }),
            "hang.ply: not a readable ply mesh (element face: 12 declared, but the data ends after "
            "1 line: truncated?)");
  // Assimp grows its face list without end on this one: the child's memory cap stops it at once
  // (std::bad_alloc); sanitizer builds have no cap, and there the time limit stops it.
  const std::string hang = error_of(
      [&] { detail::read_mesh_in_child(kHangingPly, "ply", "hang.ply", std::chrono::seconds(1)); });
  EXPECT_TRUE(hang == "hang.ply: not a readable ply mesh (std::bad_alloc)" ||
              hang == "hang.ply: not a readable ply mesh (the mesh reader did not finish in 1 s)")
      << hang;
  std::string no_end = ply();
  no_end.replace(no_end.find("end_header"), 10, "end_headex");
  EXPECT_EQ(error_of([&] {
              detail::read_mesh_in_child(no_end, "ply", "h.ply", std::chrono::milliseconds(1500));
            }),
            "h.ply: not a readable ply mesh (the mesh reader did not finish in 1.5 s)");
  EXPECT_EQ(error_of([&] { read_mesh(no_end, "ply", "h.ply"); }),
            "h.ply: not a readable ply mesh (its header has no end_header line)");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 20) << "a hanging reader must be killed at its limit";
  // This process still reads meshes afterwards, and the default limit grows with the size.
  EXPECT_EQ(read_mesh(ply(), "ply", "d.ply").size(), kFaces.size());
  EXPECT_EQ(mesh_reader_time_limit(0), std::chrono::seconds(60));
  EXPECT_EQ(mesh_reader_time_limit(39u << 20), std::chrono::seconds(99));
}

}  // namespace
}  // namespace hullinspect::world
