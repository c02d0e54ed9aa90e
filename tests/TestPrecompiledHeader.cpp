// The translation unit CMake builds the tests' shared precompiled header with
// (tests/CMakeLists.txt, target airtrap_test_pch). The header itself is the whole content; every
// test executable reuses it.
