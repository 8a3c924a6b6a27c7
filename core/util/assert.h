// GRASS_ASSERT: a broken precondition is a bug, not a user error: print where and abort.
#pragma once

#include <cstdio>
#include <cstdlib>

#define GRASS_ASSERT(cond)                                                                    \
    do {                                                                                      \
        if (!(cond)) {                                                                        \
            std::fprintf(stderr, "%s:%d: assertion failed: %s\n", __FILE__, __LINE__, #cond); \
            std::abort();                                                                     \
        }                                                                                     \
    } while (0)
