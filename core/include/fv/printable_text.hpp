// Text from a file, a link or the command line as it may appear in a one-line message: a hostile value must
// not move the terminal's cursor, recolour it, ring its bell, end the message early (NUL) or fill the
// screen. Every message that quotes user text goes through here.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace fv {

// `s` with control bytes (C0, DEL, and the C1 controls U+0080..U+009F, which some terminals obey), NUL and
// bytes that are not UTF-8 written as \xNN; printable UTF-8 kept. Longer than
// `max_bytes` of input, it is cut at a character boundary and ends with "..." and the full length
// ("... (1048576 bytes)").
std::string printable_text(std::string_view s, std::size_t max_bytes = 64);

// The same, between single quotes (a quote inside as \x27).
std::string quoted_text(std::string_view s, std::size_t max_bytes = 64);

// Free text from a file that is shown (a pinned curve's label, a data point's label): "" when `s` is
// printable UTF-8 of at most `max_bytes`, else one line saying what is wrong and what is allowed ("1048576
// bytes; allowed: printable text of at most 80 bytes", "a control or non-UTF-8 byte \x1B at byte 3; allowed:
// ...").
std::string text_error(std::string_view s, std::size_t max_bytes);

// How long free text from files may be (labels), in bytes.
inline constexpr std::size_t kMaxLabelBytes = 80;

} // namespace fv
