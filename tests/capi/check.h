/* The C test's checks (capi_test.c, driver_test.c): CHECK counts a condition and ends the
 * program naming the file and line of the first that fails; OK checks that a call returned
 * EL_OK. */
#ifndef EDGELAND_TESTS_CAPI_CHECK_H
#define EDGELAND_TESTS_CAPI_CHECK_H

#include <stdio.h>
#include <stdlib.h>

#include "edgeland/edgeland.h"

extern int checks;

#define CHECK(cond)                                                            \
  do {                                                                         \
    ++checks;                                                                  \
    if (!(cond)) {                                                             \
      fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
      exit(1);                                                                 \
    }                                                                          \
  } while (0)

#define OK(call) CHECK((call) == EL_OK)

/* driver_test.c */
void test_game_driver(void);

#endif
