/* t807-render-words.c -- the words over the colour bar   (render/)
 *
 * lac_render_field_words turns the keys of a result into words: the
 * figures of the book show "radial stress (MPa)", not "radial_stress
 * (MPa)".  Every key of the figures of figures/make-figures.sh is checked,
 * and that no word of the label keeps an underscore but a subscript.
 */
#include <string.h>

#include "check.h"
#include "render/lac_render_internal.h"

int
main (void)
{
  static const char *const want[][2] = {
    { "von_mises", "von Mises stress" }, { "radial_stress", "radial stress" },
    { "displacement_magnitude", "displacement |u|" },
    { "displacement_x", "displacement u_x" }, { "stress_yy", "stress sigma_yy" },
    { "stress_zz", "stress sigma_zz" }, { "s_rr", "stress sigma_rr" },
    { "lambda", "contact pressure lambda" }, { "gap", "mean gap" },
    { "u_R", "radial displacement u_R" }, { "mean gap", "mean gap" },
    { "some_new_key", "some new key" }
  };
  char buf[64];
  for (size_t k = 0; k < sizeof want / sizeof *want; k++)
    {
      const char *w = lac_render_field_words (want[k][0], buf, sizeof buf);
      check_true (w && !strcmp (w, want[k][1]), "%s: '%s', want '%s'",
                  want[k][0], w ? w : "(null)", want[k][1]);
    }
  check_true (lac_render_field_words (NULL, buf, sizeof buf) == NULL, "NULL");
  return check_summary ();
}
