/* t002: text that can be read and shown: lac_text_check finds the first
 * byte a text file must not hold (UTF-8 by RFC 3629), lac_text_escape
 * shows such bytes as \xNN, and stored messages go through it */
#include <string.h>

#include "check.h"
#include "base/lac_status.h"
#include "base/lac_text.h"

/* The offset lac_text_check gives for the n bytes of s. */
static long
first (const char *s, size_t n)
{
  return (long) lac_text_check (s, n, NULL);
}

/* A message longer than the buffer keeps its beginning and its end (the
 * reason), cut between UTF-8 characters. */
static void
test_fit (void)
{
  char path[3000], out[64];
  memset (path, 'a', sizeof path - 1);
  path[sizeof path - 1] = '\0';
  path[1000] = '/';
  lac_error_place (LAC_EIO, "s.scene:3", "cannot open '%s' (No such file "
                   "or directory)", path);
  check_true (strlen (lac_error_message ()) < 1024
              && !strncmp (lac_error_message (), "s.scene:3: cannot open 'aa",
                           26)
              && strstr (lac_error_message (), "aa...aa")
              && strstr (lac_error_message (), "aaa' (No such file or "
                         "directory)"), "a long path loses its middle, "
              "not the reason: '%.60s...'", lac_error_message ());
  lac_error_place (LAC_EIO, path, "[mesh] file = '%s': %s: cannot open",
                   path, path);
  check_true (strlen (lac_error_message ()) < 1024
              && strstr (lac_error_message (), "[mesh] file = 'aa")
              && strstr (lac_error_message (), "aa: cannot open"),
              "three long paths: each loses its middle, the words between "
              "stay: '%s'", lac_error_message ());
  check_int (lac_error_placed (), 1, "placed");
  lac_text_fit (out, sizeof out, "short");
  check_true (!strcmp (out, "short"), "fits: '%s'", out);
  lac_text_fit (out, sizeof out, "\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9"
                "\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9"
                "\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9"
                "\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9x");
  check_true (strlen (out) < sizeof out
              && lac_text_check (out, strlen (out), NULL) == strlen (out)
              && out[strlen (out) - 1] == 'x', "fitted between UTF-8 "
              "characters: '%s'", out);
}

int
main (void)
{
  char out[64];
  const char *what;
  /* good text: ASCII, tab, LF, CR LF, 2-, 3- and 4-byte UTF-8 */
  static const char good[] = "a\tb\r\nc\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80\n";
  check_int (first (good, sizeof good - 1), (long) sizeof good - 1, "good");
  check_int (first ("ab\0cd", 5), 2, "NUL");
  check_int (first ("ab\rcd", 5), 2, "CR alone");
  check_int (first ("ab\r", 3), 2, "CR at the end");
  check_int (first ("a\x1b[m", 4), 1, "escape");
  check_int (first ("a\x7f", 2), 1, "DEL");
  check_int (first ("a\xe9t\xe9", 4), 1, "Latin-1");
  check_int (first ("a\xC0\xAF", 3), 1, "overlong /");
  check_int (first ("a\xE0\x80\xAF", 4), 1, "overlong 3 bytes");
  check_int (first ("a\xED\xA0\x80", 4), 1, "surrogate");
  check_int (first ("a\xF4\x90\x80\x80", 5), 1, "above U+10FFFF");
  check_int (first ("a\xE2\x82", 3), 1, "cut short");
  check_int (first ("a\x80", 2), 1, "continuation alone");
  lac_text_check ("ab\rcd", 5, &what);
  check_true (what && strstr (what, "carriage return"), "what: CR");
  check_int (lac_text_line ("a\nb\nc", 4), 3, "line of offset 4");

  lac_text_escape (out, sizeof out, "E\x1b[31m = \xe9t\xc3\xa9\n");
  check_true (strcmp (out, "E\\x1B[31m = \\xE9t\xc3\xa9\n") == 0,
              "escape: '%s'", out);
  lac_text_escape (out, 6, "ab\x01\x02");
  check_true (strcmp (out, "ab") == 0, "escape cut before a \\xNN: '%s'",
              out);
  lac_error_set (LAC_EINVAL, "f", "key '%s'", "r\xe9\x07");
  check_message ("key 'r\\xE9\\x07'", "stored message escaped");
  lac_error_set (LAC_EINVAL, "f", "group 'a\nb'\tc");
  check_message ("group 'a\\x0Ab'\tc", "stored message on one line");
  lac_error_set (LAC_EINVAL, "f", "a\r\r\nb");    /* found by fuzz_numbers */
  check_true (!strcmp (lac_error_message (), "a\\x0D\\x0D\\x0Ab"),
              "a CR before a LF escaped with it: '%s'", lac_error_message ());
  lac_error_set (LAC_ENOMEM, "f", "%zu nodes", (size_t) 7);
  check_true (!strcmp (lac_error_message (), "out of memory: 7 nodes"),
              "ENOMEM says so: '%s'", lac_error_message ());
  lac_error_place (LAC_ENOMEM, "x.msh", "out of memory here");
  check_true (!strcmp (lac_error_message (), "x.msh: out of memory here"),
              "ENOMEM said once, after the place: '%s'",
              lac_error_message ());
  test_fit ();
  return check_summary ();
}
