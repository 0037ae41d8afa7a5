#include "support/zip_entries.hpp"

#include <gtest/gtest.h>
#include <zip.h>

namespace hullinspect::testing {

std::map<std::string, std::string> unzip(const std::string& path) {
  std::map<std::string, std::string> entries;
  int error = 0;
  zip_t* archive = zip_open(path.c_str(), ZIP_RDONLY, &error);
  if (!archive) {
    ADD_FAILURE() << path << ": not a zip archive";
    return entries;
  }
  for (zip_int64_t i = 0; i < zip_get_num_entries(archive, 0); ++i) {
    zip_stat_t st;
    zip_stat_index(archive, static_cast<zip_uint64_t>(i), 0, &st);
    std::string content(st.size, '\0');
    zip_file_t* f = zip_fopen_index(archive, static_cast<zip_uint64_t>(i), 0);
    zip_fread(f, content.data(), st.size);
    zip_fclose(f);
    entries[st.name] = content;
  }
  zip_close(archive);
  return entries;
}

}  // namespace hullinspect::testing
