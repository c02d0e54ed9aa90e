// airtrap-cli: bake, inspect and export Airtrap scenes without the editor (DESIGN §5).
#include "CliApp.h"

int main(int argc, char** argv) {
    airtrap::cli::CliApp app;
    return app.run(argc, argv);
}
