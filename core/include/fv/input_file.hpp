// Reading an input file (measured data, a GUI script) so that it never hangs and never reads without end.
//
//   path                        what happens
//   --------------------------  -------------------------------------------------------------------------
//   regular file                read, up to max_bytes (+1 byte to tell that it is larger)
//   FIFO, pipe, character       read without blocking on open; each wait for data is limited to `timeout_ms`,
//   device (/dev/fd/N, <(cmd))    so a FIFO nobody writes to is an error, not a hang
//   terminal                    refused: nobody is going to type a CSV file
//   directory, socket, block    refused, naming the file type
//   device, missing file
#pragma once

#include <cstddef>
#include <string>

namespace fv {

struct InputLimits {
    std::size_t max_bytes = 64u << 20;
    int timeout_ms = 10000; // per wait for data on a FIFO, pipe or device
};

// Reads `path` into `text` (at most limits.max_bytes + 1 bytes: a caller can tell that the file is too
// large). Returns an empty string, or a one-line reason without the path, for the caller to put after it
// ("is a directory, not a file").
std::string read_input_file(const std::string& path, std::string& text, const InputLimits& limits = {});

} // namespace fv
