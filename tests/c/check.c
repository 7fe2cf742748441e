#include <stdio.h>
#include <string.h>

#include "check.h"

int check_failures = 0;

void check_report(const char *file, int line, const char *what) {
  check_failures++;
  fprintf(stderr, "%s:%d: check failed: %s\n", file, line, what);
}

int check_contains(const char *file, int line, const char *message, const char *needle) {
  if (message != NULL && strstr(message, needle) != NULL) return 1;
  check_failures++;
  fprintf(stderr, "%s:%d: message \"%s\" does not contain \"%s\"\n", file, line,
          message ? message : "(null)", needle);
  return 0;
}

int check_summary(const char *program) {
  if (check_failures) fprintf(stderr, "%s: %d checks failed\n", program, check_failures);
  return check_failures ? 1 : 0;
}
