// frictionviz: one executable for the command line, the headless renderer and the window.
#include "cli/run_cli.hpp"

int main(int argc, char** argv) {
    return fv::cli::run_cli(argc, argv);
}
