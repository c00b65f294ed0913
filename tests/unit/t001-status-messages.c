/* t001: status codes and the stored message; a message may wrap the
 *       previous one (lac_error_set formats before it stores); the
 *       function that stored it is its origin, never part of it. */
#include <string.h>
#include "check.h"
#include "base/lac_status.h"

static int
inner (void)
{
  LAC_ERROR (LAC_ESING, "pivot %d is zero", 7);
}

static int
outer (void)
{
  int st = inner ();
  return LAC_ERRMSG (st, "solve failed (%s)", lac_error_message ());
}

int
main (void)
{
  lac_init ();
  check_int (outer (), LAC_ESING, "status passed through");
  check_true (strcmp (lac_error_message (),
                      "solve failed (pivot 7 is zero)") == 0,
              "wrapped message: '%s'", lac_error_message ());
  check_true (strcmp (lac_error_origin (), "outer") == 0, "origin '%s'",
              lac_error_origin ());
  check_int (lac_error_placed (), 0, "no place");
  lac_error_set (LAC_EIO, "--set", "bad");
  check_true (!strcmp (lac_error_message (), "--set: bad")
              && lac_error_placed (), "a place is shown: '%s'",
              lac_error_message ());
  lac_error_set (LAC_EIO, "box.scene:12", "bad");
  check_true (!strcmp (lac_error_message (), "box.scene:12: bad"),
              "a place is shown: '%s'", lac_error_message ());
  lac_error_place (LAC_EIO, "scene1", "bad");
  check_true (!strcmp (lac_error_message (), "scene1: bad"),
              "lac_error_place shows any place: '%s'", lac_error_message ());
  lac_error_clear ();
  check_true (lac_error_message ()[0] == '\0', "cleared");
  for (int s = -2; s <= 9; s++)
    check_true (lac_strerror (s)[0] != '\0', "strerror %d", s);
  lac_finalize ();
  return check_summary ();
}
