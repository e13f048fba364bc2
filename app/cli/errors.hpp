// The two ways a command can fail, mapped to exit codes in one place (main.cpp).
#pragma once

#include <stdexcept>

namespace fv::cli {

// The user asked for something that is not allowed: exit code 2, nothing written.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The request was valid but could not be carried out (e.g. a write failed): exit code 1.
struct RuntimeFailure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

inline constexpr int kExitUsage = 2;
inline constexpr int kExitFailure = 1;

} // namespace fv::cli
