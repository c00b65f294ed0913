/* replay -- run a fuzzing harness on given files, without libFuzzer
 *
 *   replay_NAME FILE...
 *
 * Linked with fuzz/fuzz_NAME.c by the ordinary compiler (make test, make
 * test-asan): each file is one input of LLVMFuzzerTestOneInput, as
 * libFuzzer would pass it.  The inputs that once crashed a harness are
 * kept in tests/bad/fuzz/NAME/ and replayed by tests/cases-bad.sh; a
 * harness that fails aborts, so the status is then a signal.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "base/lac_status.h"

int LLVMFuzzerTestOneInput (const uint8_t *data, size_t size);

/* The bytes of path in *data (malloc'd), their number in *size; 0 if
 * read. */
static int
slurp (const char *path, uint8_t **data, size_t *size)
{
  FILE *f = fopen (path, "rb");
  long n;
  int bad;
  *data = NULL;
  *size = 0;
  if (!f)
    return 1;
  bad = fseek (f, 0, SEEK_END) != 0 || (n = ftell (f)) < 0
        || fseek (f, 0, SEEK_SET) != 0
        || !(*data = malloc ((size_t) n + 1))
        || fread (*data, 1, (size_t) n, f) != (size_t) n;
  if (!bad)
    *size = (size_t) n;
  fclose (f);
  return bad;
}

int
main (int argc, char **argv)
{
  int bad = 0;
  lac_init ();
  for (int i = 1; i < argc; i++)
    {
      uint8_t *data;
      size_t size;
      if (slurp (argv[i], &data, &size))
        {
          fprintf (stderr, "replay: cannot read %s\n", argv[i]);
          bad = 1;
        }
      else
        LLVMFuzzerTestOneInput (data, size);
      free (data);
    }
  lac_finalize ();
  return bad;
}
