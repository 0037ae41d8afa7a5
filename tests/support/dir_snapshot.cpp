#include "support/dir_snapshot.hpp"

#include <fstream>
#include <sstream>

namespace hullinspect::testing {

namespace fs = std::filesystem;

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string rel = fs::relative(e.path(), dir).string();
    if (e.is_symlink()) {
      out[rel] = "symlink:" + fs::read_symlink(e.path()).string();
    } else if (e.is_regular_file()) {
      out[rel] = "file:" + slurp(e.path());
    } else if (e.is_directory()) {
      out[rel] = "dir";
    } else {
      out[rel] = "other";
    }
  }
  return out;
}

}  // namespace hullinspect::testing
