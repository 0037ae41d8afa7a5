// Journals (append-only CSV files) and CSV fields: torn last lines are dropped, anything else
// malformed is an error naming the file and line.

#include <gtest/gtest.h>

#include "experiment_test_support.hpp"
#include "hullinspect/core/errors.hpp"
#include "hullinspect/experiment/csv.hpp"
#include "hullinspect/experiment/journal.hpp"

namespace hullinspect::experiment {
namespace {

using testing::read;
using testing::ScratchDir;

const std::vector<std::string> kHeader = {"run_id", "a", "b"};

TEST(Csv, FieldsRoundTrip) {
  const std::vector<std::string> fields = {"plain", "with,comma", "with \"quote\"", "", "x"};
  const std::string line = csv_line(fields);
  EXPECT_EQ(line, "plain,\"with,comma\",\"with \"\"quote\"\"\",,x");
  EXPECT_EQ(split_csv_line(line), fields);
  EXPECT_EQ(split_csv_line(""), (std::vector<std::string>{""}));
  EXPECT_FALSE(split_csv_line("\"open").has_value());
  EXPECT_FALSE(split_csv_line("a\"b").has_value());
}

TEST(Journal, AppendsAndReadsBack) {
  ScratchDir dir("journal");
  const auto path = dir / "j.csv";
  {
    JournalWriter writer(path, kHeader, {"r1,1,2"});
    writer.append("r2,3,4");
    writer.append("r3,\"5,5\",6");
  }
  EXPECT_EQ(read(path), "run_id,a,b\nr1,1,2\nr2,3,4\nr3,\"5,5\",6\n");
  const auto rows = read_journal(path, kHeader);
  EXPECT_FALSE(rows.torn);
  EXPECT_EQ(rows.lines, (std::vector<std::string>{"r1,1,2", "r2,3,4", "r3,\"5,5\",6"}));
  EXPECT_EQ(line_id(rows.lines[2]), "r3");
}

TEST(Journal, DropsATornLastLine) {
  ScratchDir dir("torn");
  const auto path = dir / "j.csv";
  io::write_file_atomic(path, "run_id,a,b\nr1,1,2\nr2,3");
  const auto rows = read_journal(path, kHeader);
  EXPECT_TRUE(rows.torn);
  EXPECT_EQ(rows.lines, std::vector<std::string>{"r1,1,2"});
  // Even a torn line that happens to have the right number of fields.
  io::write_file_atomic(path, "run_id,a,b\nr1,1,2\nr2,3,4");
  EXPECT_EQ(read_journal(path, kHeader).lines.size(), 1u);
  // A torn header: nothing was recorded yet.
  io::write_file_atomic(path, "run_id,a");
  const auto empty = read_journal(path, kHeader);
  EXPECT_TRUE(empty.torn);
  EXPECT_TRUE(empty.lines.empty());
  EXPECT_TRUE(read_journal(dir / "missing.csv", kHeader).lines.empty());
  // Rewriting (as --resume does) leaves a clean file to append to.
  io::write_file_atomic(path, "run_id,a,b\nr1,1,2\nr2,3");
  {
    JournalWriter writer(path, kHeader, read_journal(path, kHeader).lines);
    writer.append("r2,3,4");
  }
  EXPECT_EQ(read(path), "run_id,a,b\nr1,1,2\nr2,3,4\n");
}

TEST(Journal, OtherDamageIsAnError) {
  ScratchDir dir("damage");
  const auto path = dir / "j.csv";
  io::write_file_atomic(path, "run_id,a,b\nr1,1,2\nr2,3\nr3,4,5\n");
  try {
    read_journal(path, kHeader);
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path.string() + ":3: malformed row (2 fields; expected 3)");
  }
  io::write_file_atomic(path, "run_id,a,c\nr1,1,2\n");
  try {
    read_journal(path, kHeader);
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              path.string() + ":1: unexpected header (written by another version of hullinspect?)");
  }
}

TEST(Csv, ParseCsvRejectsAnUnterminatedFile) {
  EXPECT_EQ(parse_csv("x,y\n1,2\n", "t.csv").rows.size(), 1u);
  try {
    parse_csv("x,y\n1,2", "t.csv");
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "t.csv:2: the last line is not terminated (a torn write?)");
  }
  EXPECT_THROW(parse_csv("x,y\n1,2,3\n", "t.csv"), InputError);
}

}  // namespace
}  // namespace hullinspect::experiment
