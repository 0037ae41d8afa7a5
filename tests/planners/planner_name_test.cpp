// Planner names appear in configs, runs.csv rows, command lines and messages: a name that would
// need quoting there is refused when it is registered, from C++ (PlannerRegistration) as from
// Python (register_planner calls the same check).

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/registry_name.hpp"
#include "hullinspect/planners/planner.hpp"

namespace hullinspect::planners {
namespace {

struct NoOptions {};

class Idle final : public Planner {
 public:
  void start(const PlannerContext&) override {}
  void decide(const sim::PlannerView&, std::span<sim::Action> actions) override {
    for (auto& a : actions) a = sim::Action::kHover;
  }
};

std::string registration_error(const std::string& name) {
  try {
    PlannerRegistration r(make_entry<Planner, NoOptions>(
        name, "test", Params<NoOptions>(name),
        [](const NoOptions&) { return std::unique_ptr<Planner>(std::make_unique<Idle>()); }));
  } catch (const ParameterError& e) {
    return user_message(e);
  }
  return "registered";
}

TEST(PlannerNames, NamesThatNeedQuotingAreRefused) {
  const std::string rule =
      "--algorithm: a planner name must be 1 to 64 letters, digits, '-', '_' or '.', starting "
      "with a letter or digit (got '";
  EXPECT_EQ(registration_error(""), rule + "')");
  EXPECT_EQ(registration_error("two\nlines"), rule + "two\\nlines')");
  EXPECT_EQ(registration_error("say \"hi\""), rule + "say \"hi\"')");
  EXPECT_EQ(registration_error("it's"), rule + "it's')");
  EXPECT_EQ(registration_error("a,b"), rule + "a,b')");
  EXPECT_EQ(registration_error("-dash-first"), rule + "-dash-first')");
  EXPECT_EQ(registration_error(std::string(65, 'a')), rule + std::string(60, 'a') + "…')");
  for (const char* refused : {"", "two\nlines", "it's"}) EXPECT_FALSE(planners().contains(refused));
}

TEST(PlannerNames, OrdinaryNamesAreAccepted) {
  EXPECT_NO_THROW(check_registry_name("planner", "algorithm", "my-planner_2.v1"));
  EXPECT_NO_THROW(check_registry_name("planner", "algorithm", std::string(64, 'a')));
  // (No planner is registered here: the tests that iterate the registry would fly it.)
  // Every built-in name follows the rule.
  for (const auto& info : planner_registry()) {
    EXPECT_NO_THROW(check_registry_name("planner", "algorithm", info.name)) << info.name;
  }
}

}  // namespace
}  // namespace hullinspect::planners
