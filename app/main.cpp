// frictionviz: one executable for the command line, the headless renderer and the window.
#include "cli/run_cli.hpp"

#include "fv/atomic_file.hpp"

#include <cstdio>

int main(int argc, char** argv) {
    // Line-buffered even into a file or pipe: a progress line ("wrote fig8.png ...") is out as soon as it is
    // printed, so a run killed later (kill -9, a CI timeout) still shows what it finished.
    std::setvbuf(stdout, nullptr, _IOLBF, 0);
    // Ctrl-C or a kill during a write removes the temporary file and exits 130 / 143; the target stays.
    fv::install_interrupt_cleanup();
    return fv::cli::run_cli(argc, argv);
}
