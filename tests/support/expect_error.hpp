// Test helper: a call that must throw curvetext::Error with a given code and
// a message containing a given part.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "curvetext/error.hpp"

namespace curvetext::testing {

template <typename F>
void expect_error(F&& call, ErrorCode code, const std::string& part) {
  try {
    call();
    ADD_FAILURE() << "no error (expected one mentioning '" << part << "')";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), code) << e.what();
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

}  // namespace curvetext::testing
