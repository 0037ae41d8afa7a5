#include "hullinspect/core/plural.hpp"

#include <gtest/gtest.h>

namespace hullinspect {
namespace {

TEST(Plural, OneIsSingularEverythingElsePlural) {
  EXPECT_EQ(plural(1, "UAV"), "1 UAV");
  EXPECT_EQ(plural(4, "UAV"), "4 UAVs");
  EXPECT_EQ(plural(0, "run"), "0 runs");
  EXPECT_EQ(plural(-1, "cell"), "-1 cells");
}

TEST(Plural, IrregularPluralIsUsedOnlyForCountsOtherThanOne) {
  EXPECT_EQ(plural(1, "directory", "directories"), "1 directory");
  EXPECT_EQ(plural(2, "directory", "directories"), "2 directories");
  EXPECT_EQ(plural_noun(3, "cell"), "cells");
  EXPECT_EQ(plural_noun(1, "cell"), "cell");
}

}  // namespace
}  // namespace hullinspect
