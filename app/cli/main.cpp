// airtrap-cli: bake, inspect and export Airtrap scenes without the editor (docs/CLI.md).
#include "CliApp.h"

int main(int argc, char** argv) {
    airtrap::cli::CliApp app;
    return app.run(argc, argv);
}
