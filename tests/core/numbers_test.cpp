// The shared number parser: exact integers with range checks, finite reals, one-line messages.

#include "hullinspect/core/numbers.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <string>

namespace hullinspect {
namespace {

std::string problem_of_uint64(const std::string& text) {
  try {
    parse_integer<std::uint64_t>(text);
  } catch (const NumberError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(Numbers, ParsesIntegersExactly) {
  EXPECT_EQ(parse_integer<int>("0"), 0);
  EXPECT_EQ(parse_integer<int>("-17"), -17);
  EXPECT_EQ(parse_integer<int>("2147483647"), std::numeric_limits<int>::max());
  EXPECT_EQ(parse_integer<int>("-2147483648"), std::numeric_limits<int>::min());
  EXPECT_EQ(parse_integer<std::uint64_t>("18446744073709551615"),
            std::numeric_limits<std::uint64_t>::max());
  EXPECT_EQ(parse_integer<std::int64_t>("-9223372036854775808"),
            std::numeric_limits<std::int64_t>::min());
}

TEST(Numbers, RefusesWhatWouldWrapOrRound) {
  EXPECT_EQ(problem_of_uint64("-1"), "must be an integer in [0, 18446744073709551615] (got '-1')");
  EXPECT_EQ(problem_of_uint64("18446744073709551616"),
            "must be an integer in [0, 18446744073709551615] (got '18446744073709551616')");
  EXPECT_EQ(problem_of_uint64("1e23"),
            "must be an integer in [0, 18446744073709551615] (got '1e23')");
  for (const char* bad : {"4294967306", "2147483648", "-2147483649", "1.0", "1e3", "+1", " 1", "1 ",
                          "", "-", "0x10", "١"}) {
    EXPECT_THROW(parse_integer<int>(bad), NumberError) << bad;
  }
  EXPECT_THROW(parse_integer<int>("11", 0, 10), NumberError);
  EXPECT_THROW(parse_integer<int>("-1", 0, 10), NumberError);
  EXPECT_EQ(parse_integer<int>("10", 0, 10), 10);
}

TEST(Numbers, ParsesFiniteRealsInRange) {
  EXPECT_DOUBLE_EQ(parse_real("0.25"), 0.25);
  EXPECT_DOUBLE_EQ(parse_real("-1e3"), -1000.0);
  EXPECT_DOUBLE_EQ(parse_real("90", 0, 180), 90.0);
  for (const char* bad : {"nan", "NaN", "inf", "-inf", "infinity", "1e400", "-1e400", "1e16",
                          "0x1p3", "1,5", "", ".", "1e", "+1", " 1"}) {
    EXPECT_THROW(parse_real(bad), NumberError) << bad;
  }
  EXPECT_THROW(parse_real("180.0001", 0, 180), NumberError);
  try {
    parse_real("nan", 0, 1);
    FAIL();
  } catch (const NumberError& e) {
    EXPECT_STREQ(e.what(), "must be a number in [0, 1] (got 'nan')");
  }
}

TEST(Numbers, ChecksDecodedReals) {
  EXPECT_DOUBLE_EQ(check_real(3.5), 3.5);
  EXPECT_THROW(check_real(std::numeric_limits<double>::infinity()), NumberError);
  EXPECT_THROW(check_real(std::numeric_limits<double>::quiet_NaN()), NumberError);
  EXPECT_THROW(check_real(2e15), NumberError);
}

TEST(Numbers, EscapesInputBytesOntoOneLine) {
  EXPECT_EQ(escape_for_message("a\nb\tc\\d\x01\xff"), "a\\nb\\tc\\\\d\\x01\\xff");
  EXPECT_EQ(escape_for_message(std::string(100, 'x'), 5), "xxxxx…");
  try {
    parse_integer<int>("1\n2");
    FAIL();
  } catch (const NumberError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
  }
}

}  // namespace
}  // namespace hullinspect
