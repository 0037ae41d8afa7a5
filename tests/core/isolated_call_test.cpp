// run_isolated: the child's output comes back whole; a crash, a hang, an exit status or an
// exception in the child is a failure of the call, never of the calling process.
#include "hullinspect/core/isolated_call.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

namespace hullinspect {
namespace {

using std::chrono::milliseconds;

TEST(IsolatedCall, ReturnsTheChildsOutputWhole) {
  const IsolatedResult r =
      run_isolated([] { return std::string("triangles"); }, milliseconds(20000));
  EXPECT_TRUE(r.ok) << r.failure;
  EXPECT_EQ(r.output, "triangles");
  EXPECT_EQ(r.failure, "");
}

TEST(IsolatedCall, ReturnsLargeBinaryOutputsByteForByte) {
  // Larger than any pipe buffer: the parent must read while the child writes.
  std::string expected(9'000'003, '\0');
  for (std::size_t i = 0; i < expected.size(); ++i) expected[i] = static_cast<char>(i * 131 % 251);
  const IsolatedResult r = run_isolated([&] { return expected; }, milliseconds(60000));
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_TRUE(r.output == expected);
  const IsolatedResult empty = run_isolated([] { return std::string(); }, milliseconds(20000));
  EXPECT_TRUE(empty.ok) << empty.failure;
  EXPECT_EQ(empty.output, "");
}

TEST(IsolatedCall, TheChildCannotChangeTheParent) {
  int value = 1;
  const IsolatedResult r = run_isolated(
      [&] {
        value = 2;
        return std::to_string(value);
      },
      milliseconds(20000));
  EXPECT_EQ(r.output, "2");
  EXPECT_EQ(value, 1);
}

TEST(IsolatedCall, ACrashIsAFailureNamingTheSignal) {
  const IsolatedResult segv = run_isolated(
      [] {
        std::raise(SIGSEGV);
        return std::string("unreachable");
      },
      milliseconds(20000));
  EXPECT_FALSE(segv.ok);
  EXPECT_EQ(segv.failure, "crashed: signal 11");
  const IsolatedResult abrt =
      run_isolated([]() -> std::string { std::abort(); }, milliseconds(20000));
  EXPECT_EQ(abrt.failure, "crashed: signal 6");
}

TEST(IsolatedCall, AnExitStatusOrAnExceptionIsAFailure) {
  const IsolatedResult exited =
      run_isolated([]() -> std::string { ::_exit(3); }, milliseconds(20000));
  EXPECT_FALSE(exited.ok);
  EXPECT_EQ(exited.failure, "exited with status 3");
  // Ending with status 0 before the output is sent is not success either.
  const IsolatedResult quiet =
      run_isolated([]() -> std::string { ::_exit(0); }, milliseconds(20000));
  EXPECT_FALSE(quiet.ok);
  EXPECT_EQ(quiet.failure, "ended before sending its whole result");
  const IsolatedResult threw =
      run_isolated([]() -> std::string { throw std::runtime_error("x"); }, milliseconds(20000));
  EXPECT_EQ(threw.failure, "exited with status 121");
}

TEST(IsolatedCall, AHangIsCutOffAtTheLimit) {
  const auto start = std::chrono::steady_clock::now();
  const IsolatedResult r = run_isolated(
      []() -> std::string {
        while (true) ::pause();
      },
      milliseconds(500));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.failure, "did not finish in 0.5 s");
  EXPECT_GE(seconds, 0.5);
  EXPECT_LT(seconds, 10) << "the child must be killed at the limit, not waited for";
}

TEST(IsolatedCall, CallsFromSeveralThreadsAtOnceGetTheirOwnOutputs) {
  // Each thread's pipe must not be held open by another thread's child, and each result must be
  // the one its own child sent.
#if defined(__SANITIZE_ADDRESS__) || defined(HULLINSPECT_SANITIZED)
  // clang-14's ASan allocator has no fork handlers: a child forked while another thread holds
  // its lock never gets memory and ends at the time limit ("did not finish"; seen here). That is
  // the caveat of core/isolated_call.hpp, which hullinspect avoids by importing meshes before it
  // starts threads; glibc's malloc (every other build) is reset in the child.
  GTEST_SKIP() << "ASan's allocator is not fork-safe with threads (clang 14)";
#endif
  std::vector<std::string> got(4);
  std::vector<std::string> failures(4);
  {
    std::vector<std::jthread> threads;
    for (int t = 0; t < 4; ++t) {
      threads.emplace_back([t, &got, &failures] {
        for (int k = 0; k < 5; ++k) {
          const IsolatedResult r = run_isolated(
              [t, k]() -> std::string {
                if (k == 2 && t % 2 == 0) std::raise(SIGSEGV);
                return std::string(100'000 + static_cast<std::size_t>(t),
                                   static_cast<char>('a' + t));
              },
              milliseconds(60000));
          if (r.ok) {
            got[static_cast<std::size_t>(t)] += r.output.substr(0, 1);
            if (r.output.size() != 100'000u + static_cast<std::size_t>(t))
              got[static_cast<std::size_t>(t)] += "!";
          } else {
            failures[static_cast<std::size_t>(t)] += r.failure + ";";
          }
        }
      });
    }
  }
  EXPECT_EQ(got[0], "aaaa");
  EXPECT_EQ(got[1], "bbbbb");
  EXPECT_EQ(got[2], "cccc");
  EXPECT_EQ(got[3], "ddddd");
  EXPECT_EQ(failures[0], "crashed: signal 11;");
  EXPECT_EQ(failures[1], "");
  EXPECT_EQ(failures[2], "crashed: signal 11;");
  EXPECT_EQ(failures[3], "");
}

}  // namespace
}  // namespace hullinspect
