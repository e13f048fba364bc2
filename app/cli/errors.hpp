// The ways a command can fail, mapped to exit codes in one place (run_cli.cpp).
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

// The computation ran but a result is not one the solver vouches for (a steady state not reached, the
// integrator gave up, a value that is not a finite number): exit code 3. Thrown only after the output,
// with each result's status, has been written; what() is one line naming the reason.
struct NumericalFailure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

inline constexpr int kExitUsage = 2;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitNumerical = 3;

} // namespace fv::cli
