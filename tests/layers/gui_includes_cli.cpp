// Must not compile: the app (gui) is below the command line, which glues it to the animation export.
#include "cli/run_cli.hpp"
