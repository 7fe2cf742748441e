/* A tiny assertion kit for the C tests: CHECK counts failures and reports
 * the file and line; each test program returns check_summary(). */
#ifndef WEFT_TEST_CHECK_H
#define WEFT_TEST_CHECK_H

#include <stdio.h>

#include "weft.h"

extern int check_failures;
void check_report(const char *file, int line, const char *what);
int check_summary(const char *program);
/* True when `message` contains `needle` (and reports it otherwise). */
int check_contains(const char *file, int line, const char *message, const char *needle);

#define CHECK(cond) ((cond) ? (void)0 : check_report(__FILE__, __LINE__, #cond))
#define CHECK_STATUS(call, expected) \
  do { WeftStatus check_s_ = (call); if (check_s_ != (expected)) { \
    check_report(__FILE__, __LINE__, #call " returned an unexpected status"); \
    fprintf(stderr, "  got %u, message: %s\n", (unsigned)check_s_, weft_last_error_message()); } } while (0)
#define CHECK_MESSAGE(needle) check_contains(__FILE__, __LINE__, weft_last_error_message(), (needle))

#endif
