#pragma once
// Every file a command writes goes through one OutputSet, so that a command either writes all its
// outputs or none and never destroys anything:
//   1. the command declares its inputs (add_input) and outputs (add_output / add_output_dir) and
//      calls check() BEFORE doing any work: an output that is a device, FIFO, socket or directory
//      (or, for add_output_dir, a non-directory), whose directory does not exist or is not
//      writable, or that is the same file (same st_dev/st_ino, or the same path once resolved) as
//      an input or another output, is refused with a ParameterError naming its option (exit 2);
//      an input is a declared one or any file read through io::read_file (which registers every
//      file it opens) since the set was made, so an input option cannot be forgotten: a command
//      makes its OutputSet before it reads anything;
//   2. write() puts each output's content into a temporary beside it;
//   3. commit() checks again that no output is a file read since check(), then renames all
//      temporaries into place together at the end; if the command fails
//      before commit(), the destructor removes the temporaries and nothing was touched.
// Files inside a declared output directory (add_output_dir, then add_output of DIR/NAME) may be
// declared before the directory exists: write() creates it (with its missing parents) and, if the
// command fails before commit(), the destructor removes what it created.
// Standard output is checked by main() (a failed write or flush is an error, e.g. > /dev/full).

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "hullinspect/files/pending_temporaries.hpp"

namespace hullinspect::io {

class OutputSet {
 public:
  OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;
  ~OutputSet();

  /// A file or directory the command reads; `option` names it in messages ("hull", "trace").
  void add_input(const std::filesystem::path& path, std::string option);
  /// A file the command writes (created or replaced).
  void add_output(const std::filesystem::path& path, std::string option);
  /// A directory the command creates or writes into (it may exist; then it must be a directory).
  /// With `must_be_empty`, an existing directory that holds anything is refused, so that files of
  /// an earlier, larger output (uav2–7 beside a new 2-UAV export) are never left beside new ones.
  void add_output_dir(const std::filesystem::path& path, std::string option,
                      bool must_be_empty = false);
  /// Runs every check described above; throws ParameterError(option, …) on the first problem.
  void check() const;

  /// Writes the content of the declared output `path` to its temporary (checked write + close).
  void write(const std::filesystem::path& path, std::string_view content);
  /// Renames every written temporary over its output, in declaration order.
  void commit();

 private:
  struct Entry {
    std::filesystem::path path;
    std::string option;
    bool directory = false;
    std::filesystem::path temporary;  // empty until written
    bool must_be_empty = false;       // directories only
    PendingTemporary pending;         // lists `temporary` for a signal handler until renamed
  };
  // Throws if the output directory `out` holds anything.
  static void check_empty(const Entry& out);
  // Throws if the output `out` is a file this process has read (io::read_file registers them).
  void check_not_read(const Entry& out) const;
  // The declared output directory that is `path`'s parent, or nullptr.
  const Entry* declared_parent_dir(const std::filesystem::path& path) const;
  std::vector<Entry> inputs_;
  std::vector<Entry> outputs_;
  std::vector<std::filesystem::path> created_dirs_;  // by write(), outermost first
  std::uint64_t first_input_;  // inputs read from this io::next_input_sequence() on are its own
};

/// True if `a` and `b` name the same existing file (same device and inode), or, when either does
/// not exist, resolve to the same absolute path.
bool same_file(const std::filesystem::path& a, const std::filesystem::path& b);

}  // namespace hullinspect::io
