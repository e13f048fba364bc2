// A figure's tables as CSV files (figure_renderer.hpp): the command line's render and the Python module's
// Figure.tables both take them from here.
#include "figures/figure_renderer.hpp"
#include "figures/result_tables.hpp"

namespace fv::app {

std::string table_csv(const TableData& t) {
    if (!t.text.empty()) return t.text;
    if (!t.ratios.empty()) return ratio_table(t.ratios, Format::csv);
    SweepPoint row;
    row.result.period = t.trace;
    row.result.status = t.status;
    return trace_table(row, Format::csv);
}

std::vector<FigureTableFile> figure_tables(const FigureData& figure) {
    std::vector<FigureTableFile> out;
    for (const TableData& t : figure.tables) out.push_back({figure.id + t.suffix + ".csv", table_csv(t)});
    return out;
}

} // namespace fv::app
