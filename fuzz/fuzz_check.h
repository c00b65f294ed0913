/* fuzz_check.h -- what every harness asserts about a failure's message
 *
 * A failure is one line of text: no line feed, no byte that lac_text
 * would show as \xNN (bytes of the input must come out escaped), not
 * empty.  A harness that sees otherwise aborts, and libFuzzer keeps the
 * input as a crash.
 */
#ifndef FUZZ_CHECK_H
#define FUZZ_CHECK_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/lac_status.h"
#include "base/lac_text.h"

static void
fuzz_check_message (int status)
{
  const char *m = lac_error_message ();
  size_t n = strlen (m);
  if (status == LAC_SUCCESS)
    return;
  if (n == 0 || strchr (m, '\n') || lac_text_check (m, n, NULL) != n
      || status == LAC_ESANITY)
    {
      fprintf (stderr, "fuzz: status %d, bad message: '%s'\n", status, m);
      abort ();
    }
}

#endif /* FUZZ_CHECK_H */
