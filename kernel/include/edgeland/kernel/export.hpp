#pragma once
// Symbols are hidden by default (CMAKE_CXX_VISIBILITY_PRESET hidden); the public API opts in.
#if defined(_WIN32)
#define EDGELAND_EXPORT
#else
#define EDGELAND_EXPORT __attribute__((visibility("default")))
#endif
