#pragma once
// Append-only CSV journals: while an experiment runs, each finished run's rows are appended whole
// (one write(2) per line, no user-space buffering), so a crash or `kill -9` loses at most the line
// being written. Reading a journal back drops such a torn last line.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace hullinspect::experiment {

struct JournalRows {
  std::vector<std::string> lines;  ///< data lines without line breaks, in file order
  bool torn = false;               ///< a last line without a line break was dropped
};

/// Reads a journal. A missing or empty file (or one holding only a torn header) gives no rows. The
/// header must equal `header`; a last line without a line break is dropped (torn = true); any other
/// malformed line or one with the wrong number of fields is an InputError naming the file and line.
JournalRows read_journal(const std::filesystem::path& path, const std::vector<std::string>& header);

/// The first field of a journal line (the run id).
std::string_view line_id(std::string_view line);

class JournalWriter {
 public:
  /// Atomically replaces `path` by the header and `lines`, then opens it for appending.
  JournalWriter(const std::filesystem::path& path, const std::vector<std::string>& header,
                const std::vector<std::string>& lines);
  ~JournalWriter();
  JournalWriter(const JournalWriter&) = delete;
  JournalWriter& operator=(const JournalWriter&) = delete;

  /// Appends `line` and a line break with one write(2); not thread-safe (the runner serialises).
  void append(std::string_view line);

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  std::string buffer_;
};

}  // namespace hullinspect::experiment
