// The translation unit that builds the precompiled headers of the judges and of the test
// programs (common/CMakeLists.txt): the headers come from the build; this file adds nothing.
