/* fuzz_mesh -- libFuzzer harness: what lac's own process does with a mesh
 *                                                   (chapter 01, bad-input.md)
 *
 * gmsh itself runs in a child process (io/lac_mesh_child.h); whatever it
 * does there is not a crash of lac (fuzz_gmsh drives it).  What runs in
 * lac's process is fuzzed here, chosen by the first byte of the input:
 *
 *   even   the rest is a .msh file: the line-by-line check before gmsh
 *          (lac_msh_check_text);
 *   odd    the rest is what the child sent back through the pipe: the
 *          decoder (lac_mesh_wire_read), then, for a mesh, the checks
 *          every mesh passes before use (lac_mesh_validate, then
 *          lac_mesh_check_topology).
 *
 * Checked: a status with one line of text, or a mesh (fuzz_check.h); no
 * memory error or leak (AddressSanitizer).
 */
#include <stddef.h>
#include <stdint.h>

#include "fuzz_check.h"
#include "fem/lac_mesh_check.h"
#include "io/lac_mesh_msh_check.h"
#include "io/lac_mesh_wire.h"

int LLVMFuzzerTestOneInput (const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput (const uint8_t *data, size_t size)
{
  const char *rest = (const char *) data + 1;
  lac_mesh *m = NULL;
  char msg[256];
  int status, child;
  if (size < 1)
    return 0;
  if (data[0] % 2 == 0)
    {
      fuzz_check_message (lac_msh_check_text ("fuzz.msh", rest, size - 1));
      return 0;
    }
  status = lac_mesh_wire_read (rest, size - 1, &child, msg, sizeof msg, &m);
  fuzz_check_message (status);
  if (!status && (child == LAC_SUCCESS) != (m != NULL))
    abort ();
  if (m && !(status = lac_mesh_validate (m)))
    status = lac_mesh_check_topology (m);
  fuzz_check_message (status);
  lac_mesh_free (m);
  return 0;
}
