#pragma once
// Skipping a test that lacks what it needs (data not found, a heap it cannot measure) so that ctest reports it
// as skipped, never as passed: call `return test::skip("why");` from the test case (tests/catch_main.cpp).
#include <string>

namespace rtlab::test {

/// The exit status of a test process whose every test case skipped: the SKIP_RETURN_CODE of every
/// discovered test (tests/CMakeLists.txt).
inline constexpr int kSkipReturnCode = 77;

/// Marks the running test case skipped and prints "skipped: REASON" (a Catch2 warning). Checks made before
/// the call still count; make it the last thing the test does.
void skip(const std::string& reason);

}  // namespace rtlab::test
