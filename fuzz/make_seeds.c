/* make_seeds -- the mesh streams of the seed corpus of fuzz_mesh
 *
 *   make_seeds DIR FILE.msh|FILE.geo ...
 *
 * Reads each mesh with lac_mesh_read and writes DIR/wire-N: the byte 1
 * (fuzz_mesh's mode: a stream from the child) and the stream
 * lac_mesh_wire_write sends for it.  Built with the ordinary compiler.
 */
#include <fcntl.h>
#include <stdio.h>
#include <unistd.h>

#include "base/lac_status.h"
#include "io/lac_mesh_gmsh.h"
#include "io/lac_mesh_wire.h"

int
main (int argc, char **argv)
{
  int made = 0;
  lac_init ();
  for (int i = 2; i < argc; i++)
    {
      lac_mesh *m = NULL;
      char path[4096];
      int fd;
      lac_mesh_opts o = { 0 };
      o.flip_inverted = 1;
      if (lac_mesh_read (argv[i], &o, &m))
        continue;
      snprintf (path, sizeof path, "%s/wire-%d", argv[1], made++);
      if ((fd = open (path, O_WRONLY | O_CREAT | O_TRUNC, 0644)) >= 0)
        {
          if (write (fd, "\1", 1) != 1
              || lac_mesh_wire_write (fd, LAC_SUCCESS, NULL, m) != 0)
            fprintf (stderr, "make_seeds: cannot write %s\n", path);
          close (fd);
        }
      lac_mesh_free (m);
    }
  printf ("%d mesh streams\n", made);
  lac_finalize ();
  return 0;
}
