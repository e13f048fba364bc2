// Writing result files so that a failed run never leaves a half-written or clobbered file.
#pragma once

#include <string>
#include <string_view>

namespace fv {

// Empty if `path` can be created or replaced (its directory exists and is writable, and `path` is not a
// directory), else a one-line reason. Used to reject a bad --out before any work is done.
std::string check_writable(const std::string& path);

// Writes `data` to a temporary file beside `path`, flushes it to disk and renames it over `path`.
// Returns an empty string on success, else a one-line reason; on failure `path` is untouched and the
// temporary file is removed.
std::string write_file_atomic(const std::string& path, std::string_view data);

} // namespace fv
