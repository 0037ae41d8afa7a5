#include "hullinspect/experiment/journal.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/experiment/csv.hpp"
#include "hullinspect/files/atomic_file.hpp"
#include "hullinspect/files/bounded_read.hpp"

namespace hullinspect::experiment {

namespace {
constexpr std::size_t kMaxJournalBytes = std::size_t{16} << 30;
}  // namespace

JournalRows read_journal(const std::filesystem::path& path, const std::vector<std::string>& header) {
  JournalRows rows;
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return rows;
  // Result journals are hullinspect's own files and grow with the experiment: a generous limit
  // that only stops a device or a runaway file.
  const std::string text = io::read_file(path, kMaxJournalBytes);
  const std::string source = path.string();
  std::size_t start = 0;
  int line_number = 0;
  while (start < text.size()) {
    ++line_number;
    const std::size_t end = text.find('\n', start);
    if (end == std::string::npos) {
      rows.torn = true;  // killed while writing this line
      break;
    }
    const std::string_view line(text.data() + start, end - start);
    start = end + 1;
    const auto fields = split_csv_line(line);
    if (line_number == 1) {
      if (!fields || *fields != header) {
        throw InputError(source, 1, "unexpected header (written by another version of hullinspect?)");
      }
      continue;
    }
    if (!fields || fields->size() != header.size()) {
      throw InputError(source, line_number,
                       fmt::format("malformed row ({} fields; expected {})",
                                   fields ? fields->size() : 0, header.size()));
    }
    rows.lines.emplace_back(line);
  }
  return rows;
}

std::string_view line_id(std::string_view line) { return line.substr(0, line.find(',')); }

JournalWriter::JournalWriter(const std::filesystem::path& path,
                             const std::vector<std::string>& header,
                             const std::vector<std::string>& lines)
    : path_(path) {
  std::string content = csv_line(header) + "\n";
  for (const auto& line : lines) content += line + "\n";
  io::write_file_atomic(path, content);
  fd_ = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd_ < 0) {
    throw InputError(path.string(), 0, fmt::format("cannot open for appending: {}", std::strerror(errno)));
  }
}

JournalWriter::~JournalWriter() {
  if (fd_ >= 0) ::close(fd_);
}

void JournalWriter::append(std::string_view line) {
  buffer_.assign(line);
  buffer_ += '\n';
  std::size_t done = 0;
  while (done < buffer_.size()) {
    const ssize_t n = ::write(fd_, buffer_.data() + done, buffer_.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw InputError(path_.string(), 0, fmt::format("cannot append: {}", std::strerror(errno)));
    }
    done += static_cast<std::size_t>(n);
  }
}

}  // namespace hullinspect::experiment
