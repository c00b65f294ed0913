/* fuzz_scene -- libFuzzer harness: the scene reader with --set overrides
 *                                                   (chapter 01, bad-input.md)
 *
 * Input: the text of a scene, optionally followed by a line holding a form
 * feed alone ("\n\f\n"); each line after it is one --set KEY=VALUE (at
 * most 8; a NUL byte ends an argument, as on a command line).  The scene
 * is read as tests/bad/fuzz.scene, so that `file = box.geo` resolves.
 * Checked: the reader returns a scene or a status with one line of text
 * (fuzz_check.h), and frees what it allocated (AddressSanitizer).
 */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "fuzz_check.h"
#include "io/lac_scene.h"

#define MAXSET 8

int LLVMFuzzerTestOneInput (const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput (const uint8_t *data, size_t size)
{
  static const char sep[] = "\n\f\n";
  const char *text = (const char *) data, *end = text + size, *cut = NULL;
  char buf[MAXSET][256];
  const char *set[MAXSET];
  size_t nset = 0, len = size;
  lac_scene *sc = NULL;
  int status;
  for (size_t i = 0; i + 3 <= size && !cut; i++)
    if (memcmp (text + i, sep, 3) == 0)
      cut = text + i;
  if (cut)
    {
      const char *p = cut + 3;
      len = (size_t) (cut - text);
      while (p < end && nset < MAXSET)
        {
          const char *nl = memchr (p, '\n', (size_t) (end - p));
          size_t n = (size_t) ((nl ? nl : end) - p);
          snprintf (buf[nset], sizeof buf[nset], "%.*s", (int) n, p);
          set[nset] = buf[nset];
          nset++;
          p += n + (nl != NULL);
        }
    }
  status = lac_scene_read_buffer (text, len, "tests/bad/fuzz.scene", nset,
                                  set, &sc);
  if ((status == LAC_SUCCESS) != (sc != NULL))
    abort ();
  fuzz_check_message (status);
  lac_scene_free (sc);
  return 0;
}
