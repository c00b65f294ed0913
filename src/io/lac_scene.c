/* lac_scene.c -- reading a scene file (see lac_scene.h)
 *
 * Reading a scene takes four steps:
 *   1. capture: inih splits the text into (section, key, value) entries
 *      (lac_scene_ini.c);
 *   2. overrides: --set KEY=VALUE replaces or adds entries (ibid.);
 *   3. build: headers and entries, in file order, are checked against the
 *      section and key tables (lac_scene_keys.c) and stored in typed
 *      structs (lac_scene_ini.c);
 *   4. finish: defaults, required keys, conflicts, model-dependent keys
 *      (lac_scene_check.c).
 * The first error stops the run with a one-line message naming the line
 * (lac_scene_query.c).  This file drives the steps and frees the scene.
 */
#include "io/lac_scene.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include "io/lac_scene_check.h"
#include "io/lac_scene_ini.h"
#include "io/lac_scene_keys.h"
#include "base/lac_input.h"
#include "base/lac_mem.h"
#include "base/lac_text.h"
#include "base/lac_status.h"

static int
set_names (lac_scene *sc, const char *path)
{
  const char *slash = strrchr (path, '/'), *base = slash ? slash + 1 : path;
  size_t n = strlen (base);
  sc->path = lac_strdup (path);
  if (!slash)
    sc->dir = lac_strdup (".");
  else if (slash == path)
    sc->dir = lac_strdup ("/");
  else if ((sc->dir = lac_malloc ((size_t) (slash - path) + 1)) != NULL)
    {
      memcpy (sc->dir, path, (size_t) (slash - path));
      sc->dir[slash - path] = '\0';
    }
  if (n > 6 && strcmp (base + n - 6, ".scene") == 0)
    n -= 6;
  if ((sc->basename = lac_malloc (n + 1)) != NULL)
    {
      memcpy (sc->basename, base, n);
      sc->basename[n] = '\0';
    }
  if (!sc->path || !sc->dir || !sc->basename)
    LAC_ERROR (LAC_ENOMEM, "out of memory");
  return LAC_SUCCESS;
}

/* The text of a scene (or of a --set) holds no byte a text file does not:
 * NUL, control characters, a carriage return alone, bytes not UTF-8. */
static int
check_text (const char *path, const char *text, size_t len)
{
  const char *what, *start;
  size_t off = lac_text_check (text, len, &what), n;
  if (off == len)
    return LAC_SUCCESS;
  for (start = text + off; start > text && start[-1] != '\n'; start--)
    ;
  for (n = 0; start + n < text + len && start[n] != '\n' && start[n] != '\r'
       && start[n] != '\0' && n < 40; n++)
    ;
  return lac_scene_where_error (path, (int) lac_text_line (text, off),
                                LAC_EINVAL, "%s%s%.*s%s", what,
                                n ? ", in '" : "", (int) n, start,
                                n == 40 ? "...'" : n ? "'" : "");
}

static int
check_sets (size_t nset, const char *const *set)
{
  for (size_t k = 0; k < nset; k++)
    {
      const char *what;
      if (lac_text_check (set[k], strlen (set[k]), &what) < strlen (set[k]))
        return lac_error_set (LAC_EINVAL, "--set", "'%s': %s", set[k], what);
    }
  return LAC_SUCCESS;
}

int
lac_scene_read_string (const char *text, const char *path, size_t nset,
                       const char *const *set, lac_scene **out)
{
  lac_scene *sc;
  int status;
  *out = NULL;
  if ((status = check_text (path, text, strlen (text)))
      || (status = check_sets (nset, set)))
    return status;
  if (!(sc = lac_calloc (1, sizeof *sc)))
    LAC_ERROR (LAC_ENOMEM, "out of memory");
  lac_scene_section_defaults (SEC_SCENE, &sc->scene.sec);
  lac_scene_section_defaults (SEC_MESH, &sc->mesh.sec);
  lac_scene_section_defaults (SEC_EXACT, &sc->exact.sec);
  lac_scene_section_defaults (SEC_OUTPUT, &sc->output.sec);
  lac_scene_section_defaults (SEC_STEPS, &sc->steps.sec);
  status = set_names (sc, path);
  if (!status)
    status = lac_scene_parse (sc, text, path, nset, set);    /* steps 1-3 */
  if (!status)
    status = lac_scene_finish (sc);                          /* step 4 */
  if (status)
    lac_scene_free (sc);
  else
    *out = sc;
  return status;
}

int
lac_scene_read_buffer (const char *text, size_t len, const char *path,
                       size_t nset, const char *const *set, lac_scene **out)
{
  char *copy;
  int status;
  *out = NULL;
  if ((status = check_text (path, text, len)))           /* NUL bytes */
    return status;
  if (!(copy = lac_malloc (len + 1)))
    LAC_ERROR (LAC_ENOMEM, "out of memory reading %s", path);
  memcpy (copy, text, len);
  copy[len] = '\0';
  status = lac_scene_read_string (copy, path, nset, set, out);
  lac_free (copy);
  return status;
}

int
lac_scene_read (const char *path, size_t nset, const char *const *set,
                lac_scene **out)
{
  char *text = NULL;
  size_t len = 0;
  int status = lac_input_read (path, LAC_SCENE_MAX_BYTES, "a scene is a "
                               "small text file", &text, &len);
  *out = NULL;
  if (!status)
    status = lac_scene_read_buffer (text, len, path, nset, set, out);
  lac_free (text);
  return status;
}

static void
section_free (lac_scene_section *s)
{
  const section_spec *sp = &lac_scene_sections[s->kind];
  for (int k = 0; k < sp->nkeys; k++)
    {
      lac_free (s->key_raw[k]);
      if (sp->keys[k].type == K_STR || sp->keys[k].type == K_LIST)
        lac_free (*(void **) ((char *) s + sp->keys[k].off));
    }
  lac_free (s->name);
}

void
lac_scene_free (lac_scene *sc)
{
  if (!sc)
    return;
  section_free (&sc->scene.sec);
  section_free (&sc->mesh.sec);
  section_free (&sc->exact.sec);
  section_free (&sc->output.sec);
  section_free (&sc->steps.sec);
  lac_free (sc->mesh.path);
  for (int k = 0; k < sc->mesh.nfiles; k++)
    lac_free (sc->mesh.files[k]), lac_free (sc->mesh.paths[k]);
  for (size_t k = 0; k < sc->nmaterial; k++)
    section_free (&sc->material[k].sec);
  for (size_t k = 0; k < sc->ndirichlet; k++)
    section_free (&sc->dirichlet[k].sec);
  for (size_t k = 0; k < sc->nload; k++)
    section_free (&sc->load[k].sec);
  for (size_t k = 0; k < sc->ncontact; k++)
    section_free (&sc->contact[k].sec);
  lac_free (sc->material);
  lac_free (sc->dirichlet);
  lac_free (sc->load);
  lac_free (sc->contact);
  lac_free (sc->path);
  lac_free (sc->dir);
  lac_free (sc->basename);
  lac_free (sc);
}
