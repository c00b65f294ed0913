/* fuzz_gmsh -- libFuzzer harness: lac_mesh_read on a mutated .msh file,
 * gmsh and all                                      (chapter 01, bad-input.md)
 *
 * The input is written to a file and read by lac_mesh_read: the line
 * check, gmsh in its child process (time limit 10 s), the stream back, the
 * checks of the mesh.  A crash of gmsh is a message here, never a crash
 * of this process; each input costs a fork and gmsh's start (a few
 * milliseconds), so this harness runs hundreds, not millions, of inputs
 * a second.  Checked: a mesh, or a status with one line of text.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <unistd.h>

#include "fuzz_check.h"
#include "io/lac_mesh_gmsh.h"

int LLVMFuzzerTestOneInput (const uint8_t *data, size_t size);

int
LLVMFuzzerTestOneInput (const uint8_t *data, size_t size)
{
  static char path[64];
  lac_mesh_opts o = { 0 };
  lac_mesh *m = NULL;
  FILE *f;
  int status;
  if (!path[0])
    snprintf (path, sizeof path, "/tmp/lac-fuzz-gmsh-%ld.msh",
              (long) getpid ());
  if (!(f = fopen (path, "wb")))
    return 0;
  fwrite (data, 1, size, f);
  fclose (f);
  o.max_seconds = 10;
  o.max_memory = 1e9;
  status = lac_mesh_read (path, &o, &m);
  if ((status == LAC_SUCCESS) != (m != NULL))
    abort ();
  fuzz_check_message (status);
  lac_mesh_free (m);
  return 0;
}
