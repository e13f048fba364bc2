// `render --list`: the registered figures as a list (tsv) or as the README's table (markdown).
#pragma once

#include <string>

namespace fv::cli {

// "ID<TAB>TITLE" per line; the title ends with the flags the figure takes.
std::string figure_list_tsv();

// The README's figure table: one row per registered figure linking its picture in screenshots/, with what
// it shows and the flags it takes (the CTest readme_figure_table holds the README to it).
std::string figure_table_markdown();

} // namespace fv::cli
