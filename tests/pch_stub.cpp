// The target whose precompiled headers every test reuses (tests/CMakeLists.txt).
