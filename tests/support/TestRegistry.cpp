#include "TestRegistry.h"

#include <cstdio>

namespace airtrap::testing {

std::map<std::string, TestRunner>& TestRegistry::runners() {
    static std::map<std::string, TestRunner> byName;
    return byName;
}

bool TestRegistry::add(const char* qualifiedName, TestRunner runner) {
    // ctest names a test after its class alone: airtrap::TestViewport is run as TestViewport.
    const std::string name = qualifiedName;
    const std::size_t scope = name.rfind("::");
    const std::string className = scope == std::string::npos ? name : name.substr(scope + 2);
    return runners().emplace(className, runner).second;
}

std::vector<std::string> TestRegistry::names() {
    std::vector<std::string> result;
    for (const auto& [name, runner] : runners())
        result.push_back(name);
    return result;
}

int TestRegistry::run(const std::string& className, int argc, char** argv) {
    const auto found = runners().find(className);
    if (found == runners().end()) {
        std::fprintf(stderr, "no test class '%s' in this executable (--list names them)\n",
                     className.c_str());
        return 2;
    }
    return found->second(argc, argv);
}

} // namespace airtrap::testing
