#pragma once
// The stability tests' measurements: each case appends one JSON line per (method, input) to the file named
// by RTLAB_STABILITY_OUT (nothing when it is unset), so that scripts/stability.sh can build the report in
// docs/stability.md from what the tests counted, not from pass or fail alone.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>

namespace rtlab::stability {

/// One row of the report: `tried` inputs of kind `input` given to `method`, `failures` of them failed the
/// way `failure` says, `worst` is the largest error seen (NaN when the case measures no error), and
/// `bound` is what the method promises (the test asserts it), e.g. "0 leaks" or "none (measured only)".
struct Row {
    std::string area;
    std::string method;
    std::string input;
    std::int64_t tried = 0;
    std::int64_t failures = 0;
    std::string failure;
    double worst = std::nan("");
    std::string bound;
};

inline std::string json_escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) < 0x20) continue;
        out += c;
    }
    return out;
}

inline void record(const Row& row) {
    const char* path = std::getenv("RTLAB_STABILITY_OUT");
    if (!path || !*path) return;
    std::ofstream out(path, std::ios::app);
    char worst[64];
    if (std::isfinite(row.worst))
        std::snprintf(worst, sizeof worst, "%.6g", row.worst);
    else
        std::snprintf(worst, sizeof worst, "null");
    out << "{\"test\":\"" << json_escape(Catch::getResultCapture().getCurrentTestName()) << "\",\"area\":\""
        << json_escape(row.area) << "\",\"method\":\"" << json_escape(row.method) << "\",\"input\":\""
        << json_escape(row.input) << "\",\"tried\":" << row.tried << ",\"failures\":" << row.failures
        << ",\"failure\":\"" << json_escape(row.failure) << "\",\"worst\":" << worst << ",\"bound\":\""
        << json_escape(row.bound) << "\"}\n";
}

}  // namespace rtlab::stability
