// Mesh files → triangles, through Assimp (STL ASCII/binary, OBJ, PLY) and zlib (gzip in memory).
// Assimp 5.2 crashes, leaks and hangs on some corrupt files (found by fuzz_mesh), so it runs in a
// child process (core/isolated_call.hpp): its crash or hang becomes a one-line InputError.
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <fmt/format.h>
#include <sys/resource.h>
#include <unistd.h>
#include <zlib.h>

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define HULLINSPECT_HAS_ASAN 1
#endif
#endif
#ifndef HULLINSPECT_HAS_ASAN
#define HULLINSPECT_HAS_ASAN 0
#endif

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <string_view>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/isolated_call.hpp"
#include "hullinspect/core/numbers.hpp"
#include "hullinspect/world/mesh_hull.hpp"
#include "mesh_header_check.hpp"

namespace hullinspect::world {

using detail::check_mesh_counts;

namespace {

bool is_gzip(std::string_view bytes) {
  return bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0x1f &&
         static_cast<unsigned char>(bytes[1]) == 0x8b;
}

std::string inflate_gzip(std::string_view bytes, const std::string& source) {
  z_stream z{};
  if (inflateInit2(&z, 16 + MAX_WBITS) != Z_OK) throw InputError(source, 0, "cannot start zlib");
  std::string out;
  out.resize(std::min<std::size_t>(kMaxMeshBytes, std::max<std::size_t>(bytes.size() * 4, 4096)));
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  z.avail_in = static_cast<uInt>(bytes.size());
  std::size_t produced = 0;
  int status = Z_OK;
  while (status != Z_STREAM_END) {
    if (produced == out.size()) {
      if (out.size() >= kMaxMeshBytes) {
        inflateEnd(&z);
        throw InputError(
            source, 0, fmt::format("decompressed mesh is larger than {} MiB", kMaxMeshBytes >> 20));
      }
      out.resize(std::min(kMaxMeshBytes, out.size() * 2));
    }
    z.next_out = reinterpret_cast<Bytef*>(out.data() + produced);
    z.avail_out = static_cast<uInt>(out.size() - produced);
    status = inflate(&z, Z_NO_FLUSH);
    produced = out.size() - z.avail_out;
    if (status != Z_OK && status != Z_STREAM_END) {
      inflateEnd(&z);
      throw InputError(source, 0, "corrupt gzip data");
    }
    if (status == Z_OK && z.avail_in == 0 && z.avail_out != 0) {
      inflateEnd(&z);
      throw InputError(source, 0, "truncated gzip data");
    }
  }
  inflateEnd(&z);
  out.resize(produced);
  return out;
}

// What the child process sends back: 'T' and nine floats per triangle (Assimp's own numbers, so
// the parent's doubles are exactly what an in-process read gave), or 'E' and the problem.
constexpr char kTriangles = 'T';
constexpr char kProblem = 'E';
constexpr std::size_t kTriangleBytes = 9 * sizeof(float);

// Caps the address space of the child running Assimp, so that a count the header checks let
// through cannot take the machine's memory: what the process maps already plus 1 GiB and 32 bytes
// per byte of mesh. An allocation beyond it fails inside Assimp, which is then a failed read.
// Sanitizer builds reserve terabytes of shadow memory up front, so they run without the cap.
void cap_child_memory(std::size_t mesh_bytes) {
#if !defined(__SANITIZE_ADDRESS__) && !HULLINSPECT_HAS_ASAN
  long pages = 0;
  if (std::FILE* f = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(f, "%ld", &pages) != 1) pages = 0;
    std::fclose(f);
  }
  const std::uint64_t mapped = static_cast<std::uint64_t>(pages) * ::sysconf(_SC_PAGESIZE);
  const std::uint64_t cap = mapped + (std::uint64_t{1} << 30) + 32 * std::uint64_t{mesh_bytes};
  const struct rlimit limit { cap, cap };
  ::setrlimit(RLIMIT_AS, &limit);
#else
  (void)mesh_bytes;
#endif
}

// Runs in the child: Assimp and nothing of hullinspect's state.
std::string import_with_assimp(std::string_view bytes, const std::string& format) {
  cap_child_memory(bytes.size());
  Assimp::Importer importer;
  // Only the geometry matters: no normals, materials or vertex joining (speed).
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                              aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene = importer.ReadFileFromMemory(
      bytes.data(), bytes.size(),
      aiProcess_Triangulate | aiProcess_PreTransformVertices | aiProcess_SortByPType,
      format.c_str());
  if (scene == nullptr) {
    // Assimp's message may quote the input (megabytes of it on one line): at most 200 characters.
    std::string why = importer.GetErrorString();
    std::replace(why.begin(), why.end(), '\n', ' ');
    return kProblem +
           fmt::format("not a readable {} mesh ({})", format, escape_for_message(why, 200));
  }
  std::size_t count = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) count += mesh->mFaces[f].mNumIndices == 3;
  }
  std::string out(1, kTriangles);
  out.reserve(1 + count * kTriangleBytes);
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices != 3) continue;
      for (std::size_t k = 0; k < 3; ++k) {
        const unsigned index = face.mIndices[k];
        if (index >= mesh->mNumVertices)
          return std::string(1, kProblem) + "a face index is out of range";
        const aiVector3D& p = mesh->mVertices[index];
        const float xyz[3] = {p.x, p.y, p.z};
        out.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
      }
    }
  }
  return out;
}

}  // namespace

std::chrono::milliseconds mesh_reader_time_limit(std::size_t bytes) {
  return std::chrono::seconds(60) + std::chrono::seconds(bytes >> 20);
}

namespace detail {

std::vector<MeshTriangle> read_mesh_in_child(std::string_view bytes, const std::string& format,
                                             const std::string& source,
                                             std::chrono::milliseconds time_limit) {
  const IsolatedResult result =
      run_isolated([&] { return import_with_assimp(bytes, format); }, time_limit);
  if (!result.ok) {
    throw InputError(
        source, 0,
        fmt::format("not a readable {} mesh (the mesh reader {})", format, result.failure));
  }
  const std::string& out = result.output;
  if (!out.empty() && out[0] == kProblem) throw InputError(source, 0, out.substr(1));
  if (out.empty() || out[0] != kTriangles || (out.size() - 1) % kTriangleBytes != 0) {
    throw InputError(source, 0,
                     fmt::format("not a readable {} mesh (the mesh reader sent {} bytes that are "
                                 "not triangles)",
                                 format, out.size()));
  }
  std::vector<MeshTriangle> triangles((out.size() - 1) / kTriangleBytes);
  const char* p = out.data() + 1;
  for (MeshTriangle& t : triangles) {
    float xyz[9];
    std::memcpy(xyz, p, sizeof xyz);
    p += sizeof xyz;
    for (std::size_t k = 0; k < 3; ++k) {
      for (std::size_t c = 0; c < 3; ++c) t.v[k][c] = static_cast<double>(xyz[3 * k + c]);
    }
  }
  return triangles;
}

}  // namespace detail

std::vector<MeshTriangle> read_mesh(std::string_view bytes, std::string_view hint,
                                    const std::string& source,
                                    std::chrono::milliseconds time_limit) {
  std::string inflated;
  if (is_gzip(bytes)) {
    inflated = inflate_gzip(bytes, source);
    bytes = inflated;
  }
  if (bytes.size() > kMaxMeshBytes) {
    throw InputError(source, 0, fmt::format("mesh is larger than {} MiB", kMaxMeshBytes >> 20));
  }
  if (bytes.empty()) throw InputError(source, 0, "the mesh file is empty");
  std::string format(hint);
  std::transform(format.begin(), format.end(), format.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (format != "stl" && format != "obj" && format != "ply") {
    throw InputError(source, 0,
                     fmt::format("unknown mesh format '{}'; expected stl, obj or ply", format));
  }
  // Also refuses a PLY header without end_header, on which Assimp 5.2's reader never returns.
  check_mesh_counts(bytes, format, source);
  if (time_limit.count() <= 0) time_limit = mesh_reader_time_limit(bytes.size());
  std::vector<MeshTriangle> triangles =
      detail::read_mesh_in_child(bytes, format, source, time_limit);
  if (triangles.empty()) throw InputError(source, 0, "the mesh has no triangles");
  return triangles;
}

}  // namespace hullinspect::world
