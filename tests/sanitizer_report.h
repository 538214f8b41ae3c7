// Tests that run the program as a subprocess check its output for sanitizer reports: under
// the asan preset the program is instrumented too, and a test that expects it to fail (bad
// input) cannot tell a report's non-zero exit status from the expected one.
#pragma once

#include <gtest/gtest.h>

#include <string>

namespace sl::test {

inline void expectNoSanitizerReport(const std::string& output, const std::string& command) {
  for (const char* marker : {"ERROR: AddressSanitizer", "ERROR: LeakSanitizer", "SUMMARY: UndefinedBehaviorSanitizer"})
    EXPECT_EQ(output.find(marker), std::string::npos) << command << "\n" << output;
}

}  // namespace sl::test
