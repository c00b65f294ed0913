/* lac_status.c -- status codes and the stored error message. */
#include "base/lac_status.h"

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <gsl/gsl_errno.h>

#include "base/lac_text.h"

static _Thread_local char last_message[1024];
static _Thread_local gsl_error_handler_t *saved_gsl_handler;

int
lac_status_errno (int e)
{
  return e == ENOMEM ? LAC_ENOMEM : LAC_EIO;
}

const char *
lac_strerror (int status)
{
  switch (status)
    {
    case LAC_SUCCESS: return "success";
    case LAC_CONTINUE: return "iteration not finished";
    case LAC_EINVAL: return "invalid input";
    case LAC_EBADLEN: return "sizes do not conform";
    case LAC_ENOMEM: return "out of memory";
    case LAC_EIO: return "input/output error";
    case LAC_EDEP: return "a library dependency failed";
    case LAC_ESING: return "singular system";
    case LAC_EMAXITER: return "no convergence";
    case LAC_EADMISS: return "not admissible";
    case LAC_ESANITY: return "internal error (a bug in lac)";
    default: return "unknown status";
    }
}

const char *
lac_error_message (void)
{
  return last_message;
}

void
lac_error_clear (void)
{
  last_message[0] = '\0';
}

/* The message is formatted into a local buffer first, so an argument may
 * be the previous message (lac_error_message ()) to wrap it; what the
 * caller quotes from a file may be binary, so bytes that are not text are
 * stored as \xNN (lac_text.h). */
int
lac_error_set (int status, const char *func, const char *fmt, ...)
{
  char buf[sizeof last_message];
  va_list ap;
  int n = snprintf (buf, sizeof buf, "%s: ", func);
  if (n < 0 || (size_t) n >= sizeof buf)
    n = 0;
  if (status == LAC_ENOMEM)         /* every such message says it once */
    {
      char rest[sizeof last_message];
      va_start (ap, fmt);
      vsnprintf (rest, sizeof rest, fmt, ap);
      va_end (ap);
      size_t m = (size_t) n;
      if (!strstr (rest, "out of memory"))
        m += (size_t) snprintf (buf + m, sizeof buf - m, "out of memory: ");
      memcpy (buf + m, rest, strnlen (rest, sizeof buf - m - 1));
      buf[m + strnlen (rest, sizeof buf - m - 1)] = '\0';
    }
  else
    {
      va_start (ap, fmt);
      vsnprintf (buf + n, sizeof buf - (size_t) n, fmt, ap);
      va_end (ap);
    }
  lac_text_escape_line (last_message, sizeof last_message, buf);
  return status;
}

int
lac_error_restore (int status, const char *message)
{
  snprintf (last_message, sizeof last_message, "%s", message);
  return status;
}

void
lac_init (void)
{
  saved_gsl_handler = gsl_set_error_handler_off ();
}

void
lac_finalize (void)
{
  gsl_set_error_handler (saved_gsl_handler);
}
