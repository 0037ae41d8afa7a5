// OutputSet: outputs never destroy an input, never replace a device or directory, and a command
// that fails before commit() leaves nothing behind.

#include "hullinspect/files/output_set.hpp"

#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/files/atomic_file.hpp"
#include "hullinspect/files/bounded_read.hpp"
#include "support/cli_runner.hpp"

namespace hullinspect::io {
namespace {

namespace fs = std::filesystem;

void put(const fs::path& p, const std::string& s) {
  std::ofstream(p) << s;
}

std::string problem(const OutputSet& set) {
  try {
    set.check();
  } catch (const ParameterError& e) {
    return e.name() + ": " + e.problem();
  }
  return "ok";
}

TEST(OutputSet, RefusesAnOutputThatIsAnInputUnderAnotherName) {
  const fs::path dir = testing::make_temp_dir("output_set_same");
  put(dir / "t.json", "{}");
  fs::create_symlink(dir / "t.json", dir / "link.json");
  fs::create_hard_link(dir / "t.json", dir / "hard.json");
  for (const fs::path& out : {dir / "." / "t.json", dir / "link.json", dir / "hard.json",
                              dir / "sub" / ".." / "t.json"}) {
    fs::create_directories(dir / "sub");
    OutputSet set;
    set.add_input(dir / "t.json", "trace");
    set.add_output(out, "out");
    EXPECT_NE(problem(set).find("is the same file as the trace"), std::string::npos) << out;
  }
}

TEST(OutputSet, RefusesTwoOutputsOnOneFile) {
  const fs::path dir = testing::make_temp_dir("output_set_twice");
  OutputSet set;
  set.add_output(dir / "a.json", "trace");
  set.add_output(dir / "x" / ".." / "a.json", "html");
  fs::create_directories(dir / "x");
  EXPECT_NE(problem(set).find("html: "), std::string::npos);
  EXPECT_NE(problem(set).find("same file as the output of --trace"), std::string::npos);
}

TEST(OutputSet, RefusesDevicesFifosSocketsAndDirectories) {
  const fs::path dir = testing::make_temp_dir("output_set_kinds");
  ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0600), 0);
  const int sock = ::socket(AF_UNIX, SOCK_STREAM, 0);
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  const std::string sock_path = (dir / "sock").string();
  ASSERT_LT(sock_path.size(), sizeof addr.sun_path);
  std::copy(sock_path.begin(), sock_path.end(), addr.sun_path);
  ASSERT_EQ(::bind(sock, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
  const std::pair<fs::path, const char*> cases[] = {{"/dev/null", "a character device"},
                                                    {dir / "fifo", "a FIFO"},
                                                    {dir / "sock", "a socket"},
                                                    {dir, "a directory"}};
  for (const auto& [path, kind] : cases) {
    OutputSet set;
    set.add_output(path, "trace");
    EXPECT_EQ(problem(set), "trace: '" + path.string() + "' is " + kind +
                                "; an output must be a regular file or a new path");
  }
  ::close(sock);
  OutputSet dir_set;
  dir_set.add_output_dir("/dev/null", "out");
  EXPECT_EQ(problem(dir_set), "out: '/dev/null' is a character device, expected a directory");
}

TEST(OutputSet, RefusesAMissingDirectoryBeforeAnythingIsWritten) {
  const fs::path dir = testing::make_temp_dir("output_set_parent");
  OutputSet set;
  set.add_output(dir / "ok.json", "trace");
  set.add_output(dir / "nodir" / "x.html", "html");
  EXPECT_EQ(problem(set), "html: cannot write '" + (dir / "nodir" / "x.html").string() +
                              "': directory '" + (dir / "nodir").string() + "' does not exist");
  EXPECT_TRUE(fs::is_empty(dir));
}

// Files in a declared output directory that does not exist yet (an export's uav<k> files):
// write() creates the directory with its missing parents; abandoned, the set removes them again.
TEST(OutputSet, CreatesADeclaredDirectoryForItsFilesAndRemovesItWhenAbandoned) {
  const fs::path dir = testing::make_temp_dir("output_set_new_dir");
  const fs::path out = dir / "plans" / "today";
  const auto declare = [&](OutputSet& set) {
    set.add_output_dir(out, "export");
    set.add_output(out / "uav0.csv", "export");
    set.add_output(out / "uav1.csv", "export");
  };
  {
    OutputSet set;
    declare(set);
    EXPECT_EQ(problem(set), "ok");
    EXPECT_FALSE(fs::exists(dir / "plans"));  // nothing made by check()
    set.write(out / "uav0.csv", "0");
    EXPECT_TRUE(fs::is_directory(out));
    EXPECT_FALSE(fs::exists(out / "uav0.csv"));  // only its temporary
  }                                              // abandoned
  EXPECT_TRUE(fs::is_empty(dir));
  OutputSet set;
  declare(set);
  set.check();
  set.write(out / "uav0.csv", "0");
  set.write(out / "uav1.csv", "1");
  set.commit();
  EXPECT_EQ(read_file(out / "uav0.csv"), "0");
  EXPECT_EQ(read_file(out / "uav1.csv"), "1");
  EXPECT_EQ(std::distance(fs::directory_iterator(out), fs::directory_iterator{}), 2);
  // A file outside any declared directory still needs its directory to exist.
  OutputSet other;
  other.add_output(dir / "elsewhere" / "x.csv", "trace");
  EXPECT_EQ(problem(other), "trace: cannot write '" + (dir / "elsewhere" / "x.csv").string() +
                                "': directory '" + (dir / "elsewhere").string() +
                                "' does not exist");
}

TEST(OutputSet, CommitsTogetherAndLeavesNothingWhenAbandoned) {
  const fs::path dir = testing::make_temp_dir("output_set_commit");
  put(dir / "a.txt", "old a");
  {
    OutputSet set;
    set.add_output(dir / "a.txt", "a");
    set.add_output(dir / "b.txt", "b");
    set.check();
    set.write(dir / "a.txt", "new a");
    set.write(dir / "b.txt", "new b");
    EXPECT_EQ(read_file(dir / "a.txt"), "old a");  // nothing replaced before commit()
    EXPECT_FALSE(fs::exists(dir / "b.txt"));
  }  // abandoned: the temporaries are removed
  EXPECT_EQ(read_file(dir / "a.txt"), "old a");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 1);
  OutputSet set;
  set.add_output(dir / "a.txt", "a");
  set.add_output(dir / "b.txt", "b");
  set.check();
  set.write(dir / "a.txt", "new a");
  set.write(dir / "b.txt", "new b");
  set.commit();
  EXPECT_EQ(read_file(dir / "a.txt"), "new a");
  EXPECT_EQ(read_file(dir / "b.txt"), "new b");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 2);
}

TEST(ReadFile, StopsAtItsLimitAndRefusesDirectories) {
  const fs::path dir = testing::make_temp_dir("read_file_limit");
  put(dir / "big", std::string((1 << 20) + 1, 'x'));
  try {
    read_file(dir / "big", 1 << 20);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              (dir / "big").string() + ": is larger than the 1 MiB limit for this input");
  }
  try {
    read_file("/", 1 << 20);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "/: is a directory, expected a file");
  }
}

// What the CLI's SIGINT/SIGTERM handler calls: every temporary written but not yet renamed into
// place is listed and removed; a committed output is no longer listed and stays.
TEST(OutputSet, PendingTemporariesAreListedUntilCommitted) {
  const fs::path dir = testing::make_temp_dir("output_set_pending");
  const auto temporaries = [&] {
    int n = 0;
    for (const auto& e : fs::directory_iterator(dir)) {
      n += e.path().filename().string().find(".tmp-") != std::string::npos ? 1 : 0;
    }
    return n;
  };
  ASSERT_EQ(pending_temporaries(), 0u);
  {
    OutputSet set;
    set.add_output(dir / "a.txt", "a");
    set.add_output(dir / "b.txt", "b");
    set.check();
    set.write(dir / "a.txt", "a");
    set.write(dir / "b.txt", "b");
    EXPECT_EQ(pending_temporaries(), 2u);
    EXPECT_EQ(temporaries(), 2);
    remove_pending_temporaries();  // as the signal handler does
    EXPECT_EQ(temporaries(), 0);
  }
  EXPECT_EQ(pending_temporaries(), 0u);
  {
    OutputSet set;
    set.add_output(dir / "c.txt", "c");
    set.check();
    set.write(dir / "c.txt", "c");
    set.commit();
    EXPECT_EQ(pending_temporaries(), 0u);
    remove_pending_temporaries();
    EXPECT_TRUE(fs::exists(dir / "c.txt"));
  }
  fs::remove_all(dir);
}

// Every file read through read_file while a set exists is one of its inputs, declared or not, under
// any name: the set refuses it as an output at check() and, for files read after check(), at
// commit(), which then leaves the file as it was.
TEST(OutputSet, RefusesAnOutputThatIsAFileReadWhileTheSetExists) {
  const fs::path dir = testing::make_temp_dir("output_set_read");
  put(dir / "prior.txt", "X.\n");
  fs::create_symlink(dir / "prior.txt", dir / "link.json");
  fs::create_hard_link(dir / "prior.txt", dir / "hard.json");
  for (const fs::path& out : {dir / "prior.txt", dir / "link.json", dir / "hard.json"}) {
    {
      OutputSet set;
      read_file(dir / "prior.txt");
      set.add_output(out, "trace");
      EXPECT_EQ(problem(set), "trace: '" + out.string() + "' is the same file as the input '" +
                                  (dir / "prior.txt").string() + "'; it would be overwritten");
    }
    {
      OutputSet set;
      set.add_output(out, "trace");
      set.check();
      read_file(dir / "prior.txt");  // after check(): write() refuses, before the command prints
      EXPECT_THROW(set.write(out, "trace"), ParameterError) << out;
    }
    OutputSet set;
    set.add_output(out, "trace");
    set.check();
    set.write(out, "trace");
    read_file(dir / "prior.txt");  // after write(): only commit() can see it
    EXPECT_THROW(set.commit(), ParameterError) << out;
    EXPECT_EQ(read_file(dir / "prior.txt"), "X.\n");
    EXPECT_TRUE(fs::is_symlink(dir / "link.json"));
  }
  // A file read before the set was made belongs to earlier work, not to this set's command.
  OutputSet later;
  later.add_output(dir / "prior.txt", "trace");
  EXPECT_EQ(problem(later), "ok");
}

TEST(OutputSet, AnOutputDirectoryThatMustBeEmptyRefusesAnyEntry) {
  const fs::path dir = testing::make_temp_dir("output_set_empty");
  OutputSet fresh;
  fresh.add_output_dir(dir, "export", true);
  EXPECT_EQ(problem(fresh), "ok");
  put(dir / "uav7.csv", "old");
  put(dir / "uav2.csv", "old");
  OutputSet set;
  set.add_output_dir(dir, "export", true);
  EXPECT_EQ(problem(set), "export: '" + dir.string() +
                              "' is not empty (it holds 'uav2.csv'); give a new or empty "
                              "directory, or --force to write into it");
  OutputSet forced;
  forced.add_output_dir(dir, "export");
  EXPECT_EQ(problem(forced), "ok");
}

TEST(ReadFile, RefusesFifosAndDevicesWithoutWaiting) {
  const fs::path dir = testing::make_temp_dir("read_file_fifo");
  ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0600), 0);
  for (const auto& [path, kind] : {std::pair<fs::path, std::string>{dir / "fifo", "a FIFO"},
                                   {"/dev/zero", "a character device"}}) {
    try {
      read_file(path, 1 << 20);
      ADD_FAILURE() << path;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()),
                path.string() + ": is " + kind + ", expected a regular file");
    }
  }
}

}  // namespace
}  // namespace hullinspect::io
