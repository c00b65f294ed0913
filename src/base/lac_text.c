/* lac_text.c -- text that can be read and shown (see lac_text.h)
 *
 * UTF-8 (RFC 3629, table 3-7 of the Unicode standard): the first byte says
 * how many follow (0xC2-0xDF: 1, 0xE0-0xEF: 2, 0xF0-0xF4: 3), each
 * following byte is 0x80-0xBF, and the second byte is narrower after 0xE0
 * (0xA0-0xBF, no overlong form), 0xED (0x80-0x9F, no surrogate), 0xF0
 * (0x90-0xBF) and 0xF4 (0x80-0x8F, nothing above U+10FFFF).
 */
#include "base/lac_text.h"

#include <stdio.h>
#include <string.h>

/* The length of the UTF-8 sequence at s (n bytes left), 0 if invalid. */
static size_t
utf8_len (const unsigned char *s, size_t n)
{
  unsigned char lo = 0x80, hi = 0xBF;
  size_t len;
  if (s[0] < 0x80)
    return 1;
  if (s[0] < 0xC2 || s[0] > 0xF4)
    return 0;
  len = s[0] < 0xE0 ? 2 : s[0] < 0xF0 ? 3 : 4;
  if (s[0] == 0xE0)
    lo = 0xA0;
  else if (s[0] == 0xED)
    hi = 0x9F;
  else if (s[0] == 0xF0)
    lo = 0x90;
  else if (s[0] == 0xF4)
    hi = 0x8F;
  if (n < len || s[1] < lo || s[1] > hi)
    return 0;
  for (size_t k = 2; k < len; k++)
    if (s[k] < 0x80 || s[k] > 0xBF)
      return 0;
  return len;
}

/* Is the byte at s[i] (n bytes in all) bad, and how long is it if not? */
static const char *
bad_byte (const unsigned char *s, size_t i, size_t n, size_t *len)
{
  *len = 1;
  if (s[i] == '\0')
    return "a NUL byte (is this a text file?)";
  if (s[i] == '\r' && (i + 1 == n || s[i + 1] != '\n'))
    return "a carriage return not followed by a line feed (old Mac line "
           "ends? save the file with LF or CR LF line ends)";
  if ((s[i] < 0x20 && s[i] != '\t' && s[i] != '\n' && s[i] != '\r')
      || s[i] == 0x7F)
    return "a control character (is this a text file?)";
  if (s[i] >= 0x80 && !(*len = utf8_len (s + i, n - i)))
    return "bytes that are not UTF-8 (save the file as UTF-8 or ASCII)";
  return NULL;
}

size_t
lac_text_check (const char *text, size_t len, const char **what)
{
  const unsigned char *s = (const unsigned char *) text;
  size_t i = 0, step;
  const char *w = NULL;
  while (i < len && !(w = bad_byte (s, i, len, &step)))
    i += step;
  if (what)
    *what = w;
  return i;
}

long
lac_text_line (const char *text, size_t off)
{
  long line = 1;
  for (size_t i = 0; i < off; i++)
    line += text[i] == '\n';
  return line;
}

/* lac_text_escape (keep_lf) and lac_text_escape_line (not). */
static void
escape (char *dst, size_t size, const char *src, int keep_lf)
{
  const unsigned char *s = (const unsigned char *) src;
  size_t n = strlen (src), i = 0, o = 0, step;
  while (i < n)
    {
      const char *w = bad_byte (s, i, n, &step);
      if (s[i] == '\n')
        w = keep_lf ? NULL : "a line feed", step = 1;
      else if (s[i] == '\r' && !keep_lf)   /* its line feed goes as \x0A */
        w = "a carriage return", step = 1;
      if (w)
        {
          if (o + 5 > size)
            break;
          snprintf (dst + o, 5, "\\x%02X", s[i]);
          o += 4;
          i++;
          continue;
        }
      if (o + step + 1 > size)
        break;
      memcpy (dst + o, s + i, step);
      o += step;
      i += step;
    }
  dst[o < size ? o : size - 1] = '\0';
}

void
lac_text_escape (char *dst, size_t size, const char *src)
{
  escape (dst, size, src, 1);
}

void
lac_text_escape_line (char *dst, size_t size, const char *src)
{
  escape (dst, size, src, 0);
}

/* The largest k <= n at which s is not inside a UTF-8 sequence. */
static size_t
char_start (const char *s, size_t n)
{
  while (n > 0 && ((unsigned char) s[n] & 0xC0) == 0x80)
    n--;
  return n;
}

/* The smallest k >= n at which s is not inside a UTF-8 sequence. */
static size_t
char_next (const char *s, size_t n)
{
  while (((unsigned char) s[n] & 0xC0) == 0x80)
    n++;
  return n;
}

/* Copy src to dst (NULL: only count) with every word (a run without a
 * blank) longer than L bytes cut to about L: its first third, "...", its
 * end (a path keeps its file name).  Returns the length of the result. */
static size_t
cut_words (char *dst, const char *src, size_t L)
{
  size_t o = 0;
  for (const char *p = src; *p;)
    {
      size_t w = strcspn (p, " "), b = strspn (p + w, " ");
      size_t head = w > L ? char_start (p, L / 3) : w;
      size_t tail = w > L ? w - char_next (p, w - (L - L / 3 - 3)) : 0;
      if (dst)
        {
          memcpy (dst + o, p, head);
          if (w > L)
            memcpy (dst + o + head, "...", 3), memcpy (dst + o + head + 3,
                                                       p + w - tail, tail);
          memcpy (dst + o + head + (w > L ? 3 + tail : 0), p + w, b);
        }
      o += head + (w > L ? 3 + tail : 0) + b;
      p += w + b;
    }
  if (dst)
    dst[o] = '\0';
  return o;
}

/* The whole of src, its middle replaced by " ... ". */
static void
cut_middle (char *dst, size_t size, const char *src)
{
  static const char gap[] = " ... ";
  size_t n = strlen (src), head, tail, start;
  head = char_start (src, (size - sizeof gap) / 4);
  start = n - (size - sizeof gap - head);         /* the most that fits */
  start = char_next (src, start);                 /* a whole character */
  tail = n - start;
  memcpy (dst, src, head);
  memcpy (dst + head, gap, sizeof gap - 1);
  memcpy (dst + head + sizeof gap - 1, src + n - tail, tail);
  dst[head + sizeof gap - 1 + tail] = '\0';
}

/* Long words (paths) are shortened first, by the most that keeps every
 * word as long as possible (a bisection on the longest length kept);
 * when even words of 48 bytes leave too much, the middle goes. */
void
lac_text_fit (char *dst, size_t size, const char *src)
{
  size_t lo = 48, hi = strlen (src);
  if (hi < size || size < 256)
    {
      if (hi < size)
        snprintf (dst, size, "%s", src);
      else
        cut_middle (dst, size, src);
      return;
    }
  if (cut_words (NULL, src, lo) >= size)
    {
      cut_middle (dst, size, src);
      return;
    }
  while (lo + 1 < hi)                 /* fits at lo, not at hi */
    {
      size_t mid = lo + (hi - lo) / 2;
      if (cut_words (NULL, src, mid) < size)
        lo = mid;
      else
        hi = mid;
    }
  cut_words (dst, src, lo);
}
