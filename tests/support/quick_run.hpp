// quick_run.hpp — whether a slow test takes its reduced probe set: under
// AddressSanitizer / UndefinedBehaviorSanitizer builds, or when
// AERIAL_TEST_QUICK is set (the sky tests' reference integrals are too slow
// for the sanitizer pass with every probe).
#pragma once

#include <cstdlib>

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_UNDEFINED__)
#define AERIAL_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(undefined_behavior_sanitizer)
#define AERIAL_SANITIZED 1
#endif
#endif

namespace aerial::test {

inline bool quickRun() {
#ifdef AERIAL_SANITIZED
    return true;
#else
    return std::getenv("AERIAL_TEST_QUICK") != nullptr;
#endif
}

}  // namespace aerial::test
