// A registered figure through the installed frictionviz::figures, against the installed command line:
//   consumer_figure ID CLI_DIR OUT_DIR
// renders figure ID (its example inputs: none for the paper's figures) as PNG and SVG, writes them into
// OUT_DIR and compares them (and its tables, figure_tables) byte for byte with CLI_DIR/ID.png, CLI_DIR/ID.svg
// and CLI_DIR/ID*.csv, which `frictionviz render
// --figure ID
// --format png,svg --out CLI_DIR` wrote at the same default size (1280x800, scale 1). Exit 0 when both agree.
#include <figures/figure_renderer.hpp>

#include <fv/atomic_file.hpp>
#include <fv/figure_data.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace {

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: consumer_figure ID CLI_DIR OUT_DIR\n");
        return 2;
    }
    const std::string id = argv[1], cli_dir = argv[2], out_dir = argv[3];
    const fv::FigureData data = fv::compute_figure(fv::app::registered_figure(id));
    fv::app::FigureRenderer renderer;
    std::filesystem::create_directories(out_dir);
    int failures = 0;
    for (fv::app::PictureFormat format : {fv::app::PictureFormat::png, fv::app::PictureFormat::svg}) {
        const std::string name = id + "." + fv::app::to_string(format);
        const std::string mine = renderer.render(data, format);
        const std::string cli = read_file(cli_dir + "/" + name);
        if (const std::string err = fv::write_file_atomic(out_dir + "/" + name, mine); !err.empty()) {
            std::fprintf(stderr, "consumer_figure: %s\n", err.c_str());
            return 1;
        }
        const bool same = !cli.empty() && mine == cli;
        std::printf("%s: library %zu bytes, command line %zu bytes: %s\n", name.c_str(), mine.size(),
                    cli.size(), same ? "identical" : "DIFFERENT");
        if (!same) ++failures;
    }
    // Its tables: the CSV files the command line wrote beside the picture, from the same writer.
    for (const fv::app::FigureTableFile& t : fv::app::figure_tables(data)) {
        const std::string cli = read_file(cli_dir + "/" + t.name);
        const bool same = !cli.empty() && t.csv == cli;
        std::printf("%s: library %zu bytes, command line %zu bytes: %s\n", t.name.c_str(), t.csv.size(),
                    cli.size(), same ? "identical" : "DIFFERENT");
        if (!same) ++failures;
    }
    return failures == 0 ? 0 : 1;
}
