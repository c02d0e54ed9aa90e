// The Qt Test classes linked into one test executable, by name. Each label's tests share one
// executable (see tests/CMakeLists.txt) so the headers every test includes are compiled once per
// batch instead of once per test; ctest still runs each class in its own process.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace airtrap::testing {

// Runs one test class with the application object it needs and returns QTest::qExec's result.
using TestRunner = int (*)(int argc, char** argv);

class TestRegistry {
public:
    // Called from static initialisers (AIRTRAP_TEST_* in TestMain.h); the returned value only
    // gives the initialiser something to hold. The class is listed without its namespace.
    static bool add(const char* qualifiedName, TestRunner runner);

    static std::vector<std::string> names();
    // Runs the named class; 2 with a message on stderr if no class of that name is linked in.
    static int run(const std::string& className, int argc, char** argv);

private:
    // A function-local static: registration runs before main in an unspecified order.
    static std::map<std::string, TestRunner>& runners();
};

} // namespace airtrap::testing
