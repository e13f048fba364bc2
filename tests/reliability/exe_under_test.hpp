// The executable the reliability cases run: FV_TEST_EXE when set (to run them against another build, say the
// one before a fix, and see them fail), else this build's (FV_EXE, set by tests/reliability/CMakeLists.txt).
#pragma once

#include <cstdlib>

namespace fv::test {

inline const char* exe() {
    const char* e = std::getenv("FV_TEST_EXE");
    return e && *e ? e : FV_EXE;
}

} // namespace fv::test
