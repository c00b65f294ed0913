/* lac_cli_infsup.c -- `lac infsup SCENE`: beta_h of a contact scene
 *                                                          [LAC (10)]
 *
 * 1. read the scene with its --set overrides; refuse a scene without
 *    [contact] (no multipliers, no inf-sup constant);
 * 2. run the stages mesh, contact, material, assemble (lac_run_iterate);
 * 3. A = the H1 Gram matrix (or the stiffness K with --norm energy), the
 *    Dirichlet dofs of the run eliminated; C = the run's LAC matrix;
 *    M = diag(h_i |T^m_i cap Gamma_C|) (lac_infsup.h);
 * 4. beta_h = sqrt(lambda_min(C^T A^-1 C, M)), printed as "name = value"
 *    lines, every real with 17 significant digits (LAC_SUMMARY_REAL), and,
 *    with --vector, the least stable multiplier pattern.
 * This file belongs to the command line (see lac_cli_infsup.h): it prints.
 */
#include "cli/lac_cli.h"
#include "cli/lac_cli_infsup.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "contact/lac_infsup.h"
#include "base/lac_mem.h"
#include "io/lac_mesh_child.h"
#include "io/lac_mesh_opts.h"
#include "run/lac_run.h"
#include "run/lac_run_mesh.h"
#include "run/lac_summary.h"
#include "io/lac_scene.h"
#include "base/lac_status.h"

const char lac_cli_infsup_help[] =
  "usage: lac infsup SCENE [options]   estimate the inf-sup constant beta_h\n"
  "\n"
  "Runs the stages mesh, contact, material and assemble of a scene with a\n"
  "[contact] section, then computes the discrete inf-sup constant of the\n"
  "LAC multipliers [LAC (10)]:\n"
  "  beta_h^2 = min_mu (mu^T C^T A^-1 C mu) / (mu^T M mu),\n"
  "the smallest eigenvalue of the pencil (C^T A^-1 C, M), where C is the\n"
  "LAC matrix (one column per admissible macro-element), A the Gram matrix\n"
  "of the displacement norm (Dirichlet dofs eliminated) and M =\n"
  "diag(h_i |T^m_i cap Gamma_C|), h_i the diameter of macro-element i (an\n"
  "h-weighted L2 norm, the usual stand-in for the H^-1/2 norm).\n"
  "See chapters/11-infsup/README.md and src/contact/lac_infsup.h.\n"
  "\n"
  "options:\n"
  "  --set KEY=VALUE   override a scene key (as for lac run), repeatable;\n"
  "                    e.g. --set level=2, --set element=tri6,\n"
  "                    --set contact.NAME.epsilon=1e-6\n"
  "  --norm h1         A = H1 Gram matrix, per component grad-grad + mass /\n"
  "                    ell^2, ell the diameter of the mesh (default; positive\n"
  "                    definite even for a body held by contact alone)\n"
  "  --norm energy     A = the stiffness K (refused if a body floats)\n"
  "  --dense           form S = C^T A^-1 C and solve the k x k problem with\n"
  "                    GSL (default for k <= 1000 multipliers)\n"
  "  --sparse          shift-invert Lanczos, one saddle-point solve per step\n"
  "                    (default above 1000 multipliers)\n"
  "  --max-memory SIZE memory the run may need (8G, 500M, 2e9 bytes; default\n"
  "                    80 % of the machine's): the mesh of a .geo is refused\n"
  "                    before it is made, a mesh read once the multipliers\n"
  "                    are known, if the estimate of what lac infsup factors\n"
  "                    (the Cholesky factor of A, and on the sparse path the\n"
  "                    LU factor of the saddle-point matrix) exceeds it\n"
  "  --vector          also print the eigenvector: one line\n"
  "                    'mu i macro h_i area_i mu_i' per multiplier\n"
  "  --quiet           no progress lines on stderr\n"
  "\n"
  "stdout: 'name = value' lines: beta_h, lambda_min, lambda_2 (next\n"
  "eigenvalue; absent with a single multiplier, or when the sparse path\n"
  "did not find it), multipliers, ndof, fixed_dofs, h_max, h_min, norm, path,\n"
  "criterion_min (the smallest phibar sqrt(delta) of [LAC Def. 1] among the\n"
  "multipliers, with its macro-element), iterations, residual, least_stable\n"
  "(multiplier and macro-element where the eigenvector is largest).\n"
  "Exit status: 0 success, 1 failure (message 'lac: ...' on stderr), 2 bad\n"
  "command line.\n"
  "\n"
  "example: lac infsup chapters/08-experiments/taylor2d.scene --set level=2\n";

typedef struct args
{
  const char *scene;
  const char **set;            /* owned array, argc entries at most */
  size_t nset;
  lac_infsup_path path;
  lac_infsup_norm norm;
  double max_memory;           /* --max-memory; 0: the default      */
  int vector, quiet, help;
} args;


static int
parse (int argc, char **argv, args *a)
{
  for (int k = 1; k < argc; k++)
    {
      const char *v;
      int missing = 0;
      if ((v = lac_cli_option_value (argc, argv, &k, "--set", &missing)))
        a->set[a->nset++] = v;
      else if ((v = lac_cli_option_value (argc, argv, &k, "--max-memory",
                                          &missing)))
        {
          if (!lac_cli_max_memory ("infsup", v, &a->max_memory))
            return LAC_CLI_USAGE;
        }
      else if ((v = lac_cli_option_value (argc, argv, &k, "--norm", &missing)))
        {
          if (strcmp (v, "h1") && strcmp (v, "energy"))
            return lac_cli_usage_error ("infsup", "--norm: expected h1 or "
                                        "energy, got", v);
          a->norm = strcmp (v, "energy") ? LAC_INFSUP_NORM_H1
                    : LAC_INFSUP_NORM_ENERGY;
        }
      else if (missing)
        return lac_cli_usage_error ("infsup", "missing value after",
                                    argv[k]);
      else if (!strcmp (argv[k], "--dense"))
        a->path = LAC_INFSUP_DENSE;
      else if (!strcmp (argv[k], "--sparse"))
        a->path = LAC_INFSUP_SPARSE;
      else if (!strcmp (argv[k], "--vector"))
        a->vector = 1;
      else if (!strcmp (argv[k], "--quiet"))
        a->quiet = 1;
      else if (!strcmp (argv[k], "--help") || !strcmp (argv[k], "-h"))
        a->help = 1;
      else if (argv[k][0] == '-' && argv[k][1] != '\0')
        return lac_cli_usage_error ("infsup", "unknown option", argv[k]);
      else if (a->scene)
        return lac_cli_usage_error ("infsup", "more than one scene:",
                                    argv[k]);
      else
        a->scene = argv[k];
    }
  if (!a->scene && !a->help)
    return lac_cli_usage_error ("infsup", "no scene file given", NULL);
  return 0;
}

/* The memory the estimate needs (io/lac_mesh_opts.h): the factor of the
 * norm matrix, and on the sparse path (k multipliers above
 * LAC_INFSUP_DENSE_KMAX, or --sparse) that of the saddle-point matrix. */
static int
infsup_solve (const args *a, size_t k)
{
  int sparse = a->path == LAC_INFSUP_SPARSE
               || (a->path == LAC_INFSUP_AUTO && k > LAC_INFSUP_DENSE_KMAX);
  if (a->norm == LAC_INFSUP_NORM_ENERGY)
    return sparse ? LAC_MESH_SOLVE_INFSUP_ENERGY_SPARSE
                  : LAC_MESH_SOLVE_INFSUP_ENERGY;
  return sparse ? LAC_MESH_SOLVE_INFSUP_SPARSE : LAC_MESH_SOLVE_INFSUP;
}

/* Once the multipliers are known (after the assembly): does the
 * estimate on the mesh made fit in --max-memory?  (The mesh stage checked
 * a .geo with the dense path, the smaller, unless --sparse.)  The dense
 * path also holds S, its copy, M and the eigenvectors: 4 k x k. */
static int
check_memory (const lac_run *r, const args *a)
{
  size_t k = r->setup.data.all ? r->setup.data.all->k : 0;
  int solve = infsup_solve (a, k);
  double dense = 32.0 * (double) k * (double) k, limit = a->max_memory;
  char what[96];
  int sparse = solve == LAC_MESH_SOLVE_INFSUP_SPARSE
               || solve == LAC_MESH_SOLVE_INFSUP_ENERGY_SPARSE;
  int fits = a->path == LAC_INFSUP_AUTO && sparse
             && lac_run_mesh_bytes (r->scene, r->mesh, infsup_solve (a, 0),
                                    dense)
                <= (limit > 0 ? limit : lac_mesh_default_memory ());
  snprintf (what, sizeof what, "and %zu multipliers%s", k, fits
            ? " (more than 1000: the sparse path; --dense fits)" : "");
  return lac_run_mesh_check_solve (r->scene, r->mesh, solve,
                                   sparse ? 0 : dense, what, limit);
}

/* Stages mesh .. assemble, with one progress line each; then the memory
 * of the estimate checked on the mesh made. */
static int
run_to_assemble (lac_run *r, const args *a)
{
  int status = LAC_CONTINUE;
  while (r->stage < LAC_STAGE_SOLVE && status == LAC_CONTINUE)
    {
      int stage = r->stage;
      status = lac_run_iterate (r);
      if (!a->quiet && status == LAC_CONTINUE)
        fprintf (stderr, "lac: [%d/%d] %-9s %s (%.2f s)\n", stage + 1,
                 LAC_STAGE_SOLVE + 1, lac_run_stage_name (stage),
                 r->progress, r->time[stage]);
      if (status == LAC_CONTINUE && stage == LAC_STAGE_ASSEMBLE)
        status = check_memory (r, a) ? LAC_EINVAL : LAC_CONTINUE;
    }
  return status == LAC_CONTINUE ? LAC_SUCCESS : status;
}

/* Step 3-4: the matrices, the estimate and the printout. */
static int
estimate (lac_run *r, const args *a)
{
  const lac_contact *c = r->setup.data.all;
  char *fixed = lac_calloc (r->sys.ndof, 1);
  double *h = lac_malloc ((c->k ? c->k : 1) * sizeof *h);
  lac_csc *G = NULL, *M = NULL;
  lac_infsup *res = NULL;
  lac_infsup_opts o;
  size_t nfixed;
  int status, energy = a->norm == LAC_INFSUP_NORM_ENERGY;
  if (!fixed || !h)
    {
      status = LAC_ERRMSG (LAC_ENOMEM, "out of memory");
      goto done;
    }
  nfixed = lac_infsup_fixed_dofs (r->sys.K, fixed);        /* Dirichlet dofs */
  if ((!energy && (status = lac_infsup_gram_h1 (r->mesh, r->model, fixed,
                                                0.0, &G)))      /* A */
      || (status = lac_infsup_norm_lac (r->mesh, r->setup.macro[0], c, h,
                                        &M)))
    goto done;
  lac_infsup_opts_init (&o);
  o.path = a->path;
  if ((status = lac_infsup_estimate (energy ? r->sys.K : G, c->C, M, &o, &res)))
    goto done;
  if (!isfinite (res->beta) || !isfinite (res->lambda_min))
    {
      status = lac_error_place (LAC_EDEP, r->scene->path, "the smallest "
                                "eigenvalue of the %zu multipliers is %g, not "
                                "a finite number", c->k, res->lambda_min);
      goto done;
    }
  double hmin = HUGE_VAL, hmax = 0, cmin = HUGE_VAL;
  size_t mcrit = 0;
  for (size_t i = 0; i < c->k; i++)
    {
      hmin = fmin (hmin, h[i]), hmax = fmax (hmax, h[i]);
      if (c->crit[c->macro[i]] < cmin)                /* [LAC Def. 1] */
        cmin = c->crit[c->macro[i]], mcrit = c->macro[i];
    }
  printf ("beta_h = " LAC_SUMMARY_REAL "\n", res->beta);
  printf ("lambda_min = " LAC_SUMMARY_REAL "\n", res->lambda_min);
  if (isfinite (res->lambda_2))          /* none with one multiplier */
    printf ("lambda_2 = " LAC_SUMMARY_REAL "\n", res->lambda_2);
  printf ("multipliers = %zu\n", c->k);
  printf ("ndof = %zu\n", r->sys.ndof);
  printf ("fixed_dofs = %zu\n", nfixed);
  printf ("h_max = " LAC_SUMMARY_REAL "\n", hmax);
  printf ("h_min = " LAC_SUMMARY_REAL "\n", hmin);
  printf ("criterion_min = " LAC_SUMMARY_REAL " (macro-element %zu)\n", cmin,
          mcrit);
  printf ("norm = %s\n", energy ? "energy (A = K)" : "h1 (A = grad-grad + "
          "mass / ell^2 per component, ell = mesh diameter)");
  printf ("multiplier_norm = diag(h_i |T^m_i cap Gamma_C|)\n");
  printf ("path = %s\n", lac_infsup_path_name (res->path));
  printf ("iterations = %zu\n", res->iterations);
  printf ("residual = " LAC_SUMMARY_REAL "\n", res->residual);
  printf ("least_stable = %zu (macro-element %zu)\n", res->imax,
          c->macro[res->imax]);
  for (size_t i = 0; i < c->k && a->vector; i++)
    printf ("mu %zu %zu " LAC_SUMMARY_REAL " " LAC_SUMMARY_REAL " %+.16e\n", i,
            c->macro[i], h[i], c->area[i], res->mu[i]);
done:
  lac_infsup_free (res);
  lac_csc_free (M);
  lac_csc_free (G);
  lac_free (h);
  lac_free (fixed);
  return status;
}

int
lac_cli_infsup (int argc, char **argv)
{
  args a;
  lac_scene *sc = NULL;
  lac_run *r = NULL;
  lac_run_opts ro = { NULL, 0, 1, 0, 0, NULL, 1, 0 };
  int ret, status;
  memset (&a, 0, sizeof a);
  if (!(a.set = lac_malloc ((size_t) (argc > 0 ? argc : 1) * sizeof *a.set)))
    {
      lac_cli_print_error ("out of memory");
      return LAC_CLI_FAILURE;
    }
  if ((ret = parse (argc, argv, &a)) || a.help)
    {
      if (!ret)
        fputs (lac_cli_infsup_help, stdout);
      lac_free (a.set);
      return ret;
    }
  /* The mesh stage checks a .geo's mesh with the smaller dense path
   * unless --sparse (the multipliers are not known yet). */
  ro.max_memory = a.max_memory;
  ro.infsup_solve = infsup_solve (&a, 0);
  /* 1. The scene: it must have multipliers. */
  ret = LAC_CLI_FAILURE;
  if ((status = lac_scene_read (a.scene, a.nset, a.set, &sc)))
    lac_cli_print_failure (a.scene, status);
  else if (sc->ncontact == 0)
    fprintf (stderr, "lac: %s: no [contact] section: the inf-sup constant "
             "[LAC (10)] is a property of the contact multipliers; add a "
             "[contact NAME] section with slave and master groups\n",
             sc->path);
  else if (sc->ncontact > 1)
    fprintf (stderr, "lac: %s: %zu [contact] sections: lac infsup "
             "estimates the constant of one pair; run it on a scene with "
             "one of them\n", sc->path, sc->ncontact);
  else if (!(r = lac_run_alloc (sc, &ro)))
    lac_cli_print_failure (sc->path, LAC_ENOMEM);
  /* 2.-4. The stages up to assemble, then the estimate. */
  else if ((status = run_to_assemble (r, &a))
           || (status = estimate (r, &a)))
    lac_cli_print_failure (sc->path, status);
  else
    ret = lac_cli_flush_stdout ();
  lac_run_free (r);
  lac_scene_free (sc);
  lac_free (a.set);
  return ret;
}
