// Catch2's main, compiled once and shared by every test executable, with skips that ctest can see.
//
// Catch2 v2 has no skip: a test that lacks its data calls rtlab::test::skip() (tests/support/skip.hpp) and
// returns. ctest runs one test case per process; when every test case that ran skipped and none failed, the
// process exits with kSkipReturnCode, which the tests' SKIP_RETURN_CODE property (tests/CMakeLists.txt)
// reports as "Skipped", not as passed.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include <skip.hpp>

namespace {

int g_cases_run = 0;
int g_cases_skipped = 0;
bool g_current_skipped = false;

struct SkipCounter : Catch::TestEventListenerBase {
    using TestEventListenerBase::TestEventListenerBase;
    void testCaseStarting(const Catch::TestCaseInfo&) override {
        ++g_cases_run;
        g_current_skipped = false;
    }
    void testCaseEnded(const Catch::TestCaseStats&) override {
        if (g_current_skipped) ++g_cases_skipped;
    }
};

}  // namespace

CATCH_REGISTER_LISTENER(SkipCounter)

namespace rtlab::test {

void skip(const std::string& reason) {
    g_current_skipped = true;
    WARN("skipped: " << reason);
}

}  // namespace rtlab::test

int main(int argc, char* argv[]) {
    const int failures = Catch::Session().run(argc, argv);
    if (failures == 0 && g_cases_run > 0 && g_cases_skipped == g_cases_run) return rtlab::test::kSkipReturnCode;
    return failures;
}
