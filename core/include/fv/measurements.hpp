// Measured friction ratios r_x(zeta) read from a CSV file, with errors that point at file:line:column.
//
// Format (one header line, then one row per measurement):
//   - required columns: `zeta,r_x`, or `vb,r_x` (v_b in m/s; needs the vibration amplitude and frequency,
//     ReadOptions, to convert to zeta = v_b / (2 pi f A), see units.hpp)
//   - optional columns: `theta_deg` (vibration angle, [0, 180]), `sigma` (standard uncertainty of r_x, > 0),
//     `label` (free text, no commas; there is no quoting)
//   - any column order; spaces and tabs around fields are trimmed; lines whose first non-blank character is
//     '#' and blank lines are skipped; LF or CRLF line ends; a UTF-8 byte-order mark is skipped
//   - every numeric field must be present and read by the shared number reader (read_number.hpp, as on the
//     command line) inside the shared ranges (param_ranges.hpp): zeta in [0, 100], vb in [0, 1e6],
//     r_x in [-0.5, 1.5] (the model gives [0, 1]; the margin admits noise and calibration offsets, anything
//     further off is a unit or column mix-up such as percent), theta_deg in [0, 180], sigma in [1e-6, 10]
//     (kSigmaRange says why)
//   - label: printable UTF-8 of at most 80 bytes (kMaxLabelBytes)
//   - limits: at most ReadOptions::max_rows data rows, max_line_bytes bytes per line, max_file_bytes bytes.
#pragma once

#include "fv/param_ranges.hpp"

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace fv {

// The only exception the readers throw. what() is "FILE:LINE:COL: message" (1-based; COL counts bytes and
// points at the first non-blank byte of the offending field); the message is one line naming what is wrong
// and what is allowed, with the offending text quoted (shortened, non-printable bytes as \xNN).
struct DataError : std::runtime_error {
    DataError(std::string file, int line, int column, const std::string& message);
    std::string file;
    int line = 0, column = 0;
    std::string message;
};

struct Measurement {
    double zeta = 0;          // given, or converted from vb
    std::optional<double> vb; // the file's v_b in m/s, as given (a vb column): zeta can be converted again
    double rx = 0;
    std::optional<double> theta_deg;
    std::optional<double> sigma;
    std::string label;
    int line = 0; // where it came from
};

struct MeasurementSet {
    std::string file;
    std::vector<Measurement> points;
    bool has_theta = false, has_sigma = false; // every point has it, or none does
    bool from_vb = false;                      // zeta was converted from a vb column
    // A comment line says "synthetic" (any case), as the example files of tests/data/ do ("# SYNTHETIC DATA,
    // not measurements"): figures then call the points synthetic example data, not measurements.
    bool synthetic = false;
};

struct ReadOptions {
    std::optional<double> amplitude_um;  // needed for a vb column
    std::optional<double> frequency_khz; // needed for a vb column
    std::size_t max_rows = 100000;
    std::size_t max_line_bytes = 4096;
    std::size_t max_file_bytes = 16u << 20;
};

inline constexpr double kMinRx = kRxDataRange.lo, kMaxRx = kRxDataRange.hi, kMaxZeta = kZetaRange.hi;

// Parses `text` as the contents of a file called `name` (used in errors only).
MeasurementSet parse_measurements(std::string_view text, const std::string& name,
                                  const ReadOptions& opt = {});

// Reads and parses `path`; an unreadable file is a DataError at line 0, column 0.
MeasurementSet read_measurements(const std::string& path, const ReadOptions& opt = {});

} // namespace fv
