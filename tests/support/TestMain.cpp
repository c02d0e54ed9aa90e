// main() of every test executable: `airtrap-unit-tests TestKernel [Qt Test options]` runs one test
// class, exactly as that class's own QTEST_MAIN would; `--list` names the classes linked in.

#include "TestRegistry.h"

#include <cstdio>
#include <string>

using airtrap::testing::TestRegistry;

namespace {

int printUsage(const char* program) {
    std::fprintf(stderr, "usage: %s TestClass [Qt Test options]\n       %s --list\n", program,
                 program);
    return 2;
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2 || argv[1][0] == '-') {
        if (argc >= 2 && std::string(argv[1]) == "--list") {
            for (const std::string& name : TestRegistry::names())
                std::printf("%s\n", name.c_str());
            return 0;
        }
        return printUsage(argv[0]);
    }
    // Qt Test sees the program name followed by its own options, as under QTEST_MAIN.
    const std::string className = argv[1];
    argv[1] = argv[0];
    return TestRegistry::run(className, argc - 1, argv + 1);
}
