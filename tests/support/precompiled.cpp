// The translation unit that builds the test programs' precompiled header (glint_test_pch in
// tests/CMakeLists.txt); it has no code of its own.
