/* pngcheck.c -- measure PNG files (a helper of tests/cases-figures.sh)
 *
 *   pngcheck FILE.png...
 *
 * prints one line per file:
 *   FILE WIDTH HEIGHT INK COLOURS
 * INK the fraction of pixels that are not the background (the colour of
 * the top-left pixel, white in every figure), COLOURS the number of
 * distinct colours (counted up to 4096).  A blank or nearly blank picture
 * has INK near 0; a picture without a colour map or curves has few
 * colours.  Exit status 1 if a file is not a readable PNG.
 */
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAXC 4096

static int
check (const char *path)
{
  png_image img;
  memset (&img, 0, sizeof img);
  img.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file (&img, path))
    {
      fprintf (stderr, "pngcheck: %s: %s\n", path, img.message);
      return 1;
    }
  img.format = PNG_FORMAT_RGBA;
  unsigned char *buf = malloc (PNG_IMAGE_SIZE (img));
  if (!buf || !png_image_finish_read (&img, NULL, buf, 0, NULL))
    {
      fprintf (stderr, "pngcheck: %s: %s\n", path, buf ? img.message : "no memory");
      free (buf);
      png_image_free (&img);
      return 1;
    }
  size_t n = (size_t) img.width * img.height, ink = 0, nc = 0;
  static unsigned int col[2 * MAXC];     /* open addressing, 0: empty */
  static unsigned char used[2 * MAXC];
  unsigned int bg = 0;
  memset (used, 0, sizeof used);
  memcpy (&bg, buf, 4);
  for (size_t k = 0; k < n; k++)
    {
      unsigned int c;
      memcpy (&c, buf + 4 * k, 4);
      if (c != bg)
        ink++;
      if (nc < MAXC)
        {
          size_t j = (c * 2654435761u) % (2 * MAXC);
          while (used[j] && col[j] != c)
            j = (j + 1) % (2 * MAXC);
          if (!used[j])
            {
              used[j] = 1;
              col[j] = c;
              nc++;
            }
        }
    }
  printf ("%s %u %u %.4f %zu\n", path, img.width, img.height,
          n ? (double) ink / (double) n : 0.0, nc);
  free (buf);
  return 0;
}

int
main (int argc, char **argv)
{
  int rc = 0;
  if (argc < 2)
    {
      fprintf (stderr, "usage: pngcheck FILE.png...\n");
      return 2;
    }
  for (int a = 1; a < argc; a++)
    rc |= check (argv[a]);
  return rc;
}
