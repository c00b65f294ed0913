/* main.c -- the lac command line
 *
 *   lac run SCENE [--set KEY=VALUE]... [--solver NAME] [--strategy NAME]
 *                 [--petsc-options "..."] [--out DIR]
 *                 [--quiet] [--timings] [--no-output]
 *   mpirun -n N lac run SCENE [--strategy petsc] [...]
 *   lac infsup SCENE [...]     (lac_cli_infsup.c)
 *   lac render RESULT [...]    (lac_cli_render.c)
 *   lac --help | --version
 *
 * The only file that prints and exits.  Progress (the active effects, one
 * line per stage) goes to stderr, the summary lines "name = value" to
 * stdout (and, identical, to DIR/summary.txt); an error is one line
 * "lac: <message>" on stderr and a non-zero exit status.  On N MPI
 * processes, process 0 runs the scene (and alone prints and writes) and
 * the others serve its petsc strategy (solve/lac_petsc.h).
 */
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "cli/lac_cli.h"
#include "cli/lac_cli_infsup.h"
#include "cli/lac_cli_openblas.h"
#include "cli/lac_cli_limits.h"
#include "cli/lac_cli_render.h"
#include "linalg/lac_linalg.h"
#include "run/lac_run.h"
#include "solve/lac_newton.h"
#include "solve/lac_nonlinear.h"
#include "solve/lac_petsc.h"
#include "solve/lac_strategy.h"
#include "io/lac_output_batch.h"
#include "io/lac_mesh_opts.h"
#include "io/lac_scene.h"
#include "run/lac_run_scene.h"
#include "run/lac_run_sliding.h"
#include "base/lac_status.h"
#include "base/lac_text.h"

#ifndef LAC_VERSION
#define LAC_VERSION "0.1.0"
#endif


static const char *help_text =
  "usage: lac run SCENE [options]      solve the scene, write the results\n"
  "       lac infsup SCENE [options]   estimate the inf-sup constant beta_h\n"
  "       lac render RESULT [options]  draw a result directory as PNG\n"
  "       lac --help                   this text\n"
  "       lac --version                the version\n"
  "\n"
  "lac run reads the scene file SCENE (INI format; every section and key is\n"
  "described in chapters/01-problem/scene-format.md and src/io/lac_scene.h),\n"
  "meshes or reads the mesh with gmsh, assembles and solves the linear\n"
  "elastic problem (with contact by the LAC method, frictionless or with\n"
  "Coulomb friction, when the scene has a [contact] section), computes\n"
  "nodal stresses and, when the scene has an [exact] section, the errors\n"
  "against the exact solution.\n"
  "\n"
  "scene sections and keys (defaults in parentheses; every key is listed):\n"
  "  [scene]          title, model = plane_strain|axisymmetric|3d,\n"
  "                   element = tri3|tri6|quad4|quad8|quad9|tet4|tet10|hex8|\n"
  "                   hex20|hex27 (any), solver = dense|umfpack|cholmod\n"
  "                   (cholmod), out = DIR, large_deformation = yes|no (no;\n"
  "                   yes: hyperelasticity, load steps, one Newton loop for\n"
  "                   material, geometry and contact, re-pairing every\n"
  "                   iteration)\n"
  "  [mesh]           file = NAME.geo|NAME.msh ... (relative to the scene),\n"
  "                   size (1), order = 1|2, level (0), numbers = NAME=VALUE\n"
  "                   ... (more .geo numbers, |VALUE| < 2^31), recombine =\n"
  "                   yes|no, inverted = flip|reject (flip)\n"
  "  [material NAME]  group (all other cells), E, nu,\n"
  "                   law = linear|neo_hookean (linear)\n"
  "  [dirichlet NAME] group, and ux/uy/uz (axisymmetric ur/uz) = VALUE, or\n"
  "                   clamp = yes, or symmetry = x|y|z|r, or exact = yes, or\n"
  "                   normal = VALUE (u.n along the outward normal of a\n"
  "                   facet group: a roller for 0, on any face)\n"
  "                   (ramp = yes|no: grows with the load factor, yes;\n"
  "                   small strain: curve = T0 F0 T1 F1 ..., the value\n"
  "                   times f(t), piecewise linear)\n"
  "  [load NAME]      group, and one of pressure = P, traction = TX TY [TZ],\n"
  "                   force = FX FY [FZ] (per unit volume; group optional),\n"
  "                   exact = traction|tangential|force (from [exact]),\n"
  "                   total_force = FX FY [FZ] (spread on the group; with\n"
  "                   plate = yes the group moves as one rigid plate),\n"
  "                   point_force = FX FY [FZ] (at a point group's node);\n"
  "                   small strain: curve = T0 F0 ... (as [dirichlet];\n"
  "                   else the load times t)\n"
  "  [contact NAME]   slave = FACET_GROUP, and master = FACET_GROUP or\n"
  "                   obstacle = graph (a rigid foundation: height (0),\n"
  "                   curvature (0), center (0); normal = obstacle|slave\n"
  "                   (obstacle)), epsilon (0.01): admissibility threshold\n"
  "                   in (0, 1], method = lac|p0|nts (lac),\n"
  "                   strategy = auto|dense|schur|augmented|split|saddle|\n"
  "                   petsc (auto), max_iterations ("
  LAC_XSTR (LAC_NEWTON_MAXIT) "): active-set\n"
  "                   iterations at most, rules = all|none|LIST (all): the\n"
  "                   rules of the loop (chapter 07), gap_bound (0): a\n"
  "                   length added to the pairing distance, interference\n"
  "                   (0): a shrink fit, delta taken from every gap of the\n"
  "                   pair, interference_tolerance (0.1): the largest mean\n"
  "                   gap of a macro-element without it over delta,\n"
  "                   sliding_tolerance ("
  LAC_XSTR (LAC_SLIDING_TOLERANCE) "): the largest change of an\n"
  "                   active mean gap by the deformed shape over the\n"
  "                   normal displacement (small strain), friction (0):\n"
  "                   Coulomb's coefficient mu (chapter 15), hex_cut =\n"
  "                   auto|pyramids|six (auto); one section per contact pair\n"
  "  [exact]          solution = thick_sphere|thick_cylinder (a, b, p, E, nu)\n"
  "                   | taylor (p, E, nu: uniform pressure, patch test)\n"
  "                   | taylor_shear (p, tau, E, nu: and a uniform shear)\n"
  "                   | manufactured2d|manufactured3d (E, nu)\n"
  "                   | biaxial (p, E, nu: uniform pressure along x and y)\n"
  "  [steps]          n (1) equal load steps to the load factor end (1)\n"
  "                   after a first step to start (0), monitor =\n"
  "                   NODE_GROUP, curve = FILE (curve.csv): one line per step,\n"
  "                   vtu_every = K (0): step_NNN.vtu every K steps; large\n"
  "                   deformation: tol (" LAC_XSTR (LAC_NL_TOL)
  "), maxit (" LAC_XSTR (LAC_NL_MAXIT) "), tangent =\n"
  "                   consistent|frozen (consistent); small strain (with\n"
  "                   [contact]): one active-set loop per step\n"
  "  [output]         vtu = yes|no (yes), csv = yes|no (yes),\n"
  "                   matrix = yes|no (no), vtu_format = binary|ascii\n"
  "                   (binary), reactions = yes|no (no: reaction.NAME\n"
  "                   lines in the summary, the force of the supports)\n"
  "\n"
  "options of run:\n"
  "  --set KEY=VALUE   override a scene key after the file is read; KEY is\n"
  "                    SECTION.KEY (mesh.level=2), TYPE.NAME.KEY\n"
  "                    (material.shell.E=3000 for the [material shell] of\n"
  "                    the example below) or an alias: element, model,\n"
  "                    solver, out, level, order, size.  Repeatable.\n"
  "  --solver NAME     dense (dense LU), umfpack (sparse LU) or cholmod\n"
  "                    (sparse Cholesky, the default): same as\n"
  "                    --set scene.solver=NAME; petsc: same as --strategy\n"
  "                    petsc\n"
  "  --strategy NAME   how each active set's system is solved: auto (the\n"
  "                    default: petsc on N > 1 MPI processes, when a\n"
  "                    Cholesky factor would not fit in --max-memory, or\n"
  "                    in 3D with linear cells when it is estimated at\n"
  "                    0.9 GB or more (small strain: faster there);\n"
  "                    else dense for small systems, else schur or split;\n"
  "                    without contact, petsc in the same three cases when\n"
  "                    [scene] solver is not given), dense, schur (every\n"
  "                    body held by its Dirichlet conditions), augmented,\n"
  "                    split (bodies held by contact alone), saddle, or\n"
  "                    petsc (Krylov methods and algebraic multigrid, no\n"
  "                    factorization, on N MPI processes; also without\n"
  "                    contact and in large deformation); overrides the\n"
  "                    scene's [contact] strategy (chapters 07, 13)\n"
  "  --petsc-options \"...\"  PETSc options for the petsc strategy; they win\n"
  "                    over the environment variable PETSC_OPTIONS.  The\n"
  "                    solve of K alone (no [contact]) takes the prefix\n"
  "                    elast_ (-elast_ksp_monitor -elast_pc_type hypre),\n"
  "                    the projected CG of a contact scene none\n"
  "                    (-ksp_monitor); chapter 13 lists them.  An option\n"
  "                    that nothing read is named in a warning after the\n"
  "                    run\n"
  "  --out DIR         output directory (created if needed).  Default: the\n"
  "                    scene's [scene] out, else out/<scene name without\n"
  "                    .scene>, relative to the current directory\n"
  "  --quiet           no progress lines on stderr (errors still shown)\n"
  "  --timings         add time_<stage> lines (seconds) and\n"
  "                    peak_rss_total_mb (peak memory, MB, summed over the\n"
  "                    MPI processes) to the summary\n"
  "  --no-output       write no files (the summary still goes to stdout)\n"
  "  --max-memory SIZE memory a mesh may need (8G, 500M, 2e9 bytes; default\n"
  "                    80 % of the machine's): gmsh runs in a child process\n"
  "                    limited to it, and a .geo whose mesh is estimated to\n"
  "                    need more is refused before gmsh makes it (with the\n"
  "                    strategy auto: unless it fits with petsc, which auto\n"
  "                    then takes)\n"
  "\n"
  "output files in DIR (written beside it, in .NAME.lac-new-PID, and put in\n"
  "place all at once at the end, once the summary is on stdout: a run that\n"
  "fails, gets SIGINT or SIGTERM, or cannot write its summary leaves the\n"
  "complete files of the earlier run and no temporary; files of DIR that a\n"
  "run never writes are kept; DIR must be a writable directory):\n"
  "  solution.vtu      mesh, displacement, stresses, von Mises (ParaView;\n"
  "                    binary, or text with --set output.vtu_format=ascii)\n"
  "  nodes.csv         one row per node: coordinates, displacement, stress\n"
  "  contact.csv       one row per macro-element: centroid, measure,\n"
  "                    admissibility, lambda, mean gap, status, abscissa\n"
  "                    (2D), force ([contact]; empty field: no value)\n"
  "  contact.vtu       the slave surface: lambda, mean gap, status\n"
  "  K.mtx             the stiffness matrix, Matrix Market ([output] matrix)\n"
  "  curve.csv         with [steps]: one row per load step (load factor,\n"
  "                    imposed displacement, monitor node, iterations,\n"
  "                    contact force); contact_steps.csv: every multiplier\n"
  "                    at every step\n"
  "  step_NNN.vtu      with [steps] vtu_every = K: the\n"
  "                    fields of solution.vtu after every K-th load step and\n"
  "                    the last; steps.pvd lists them with the load factor\n"
  "                    as time (ParaView opens the series)\n"
  "  summary.txt       the summary lines printed on stdout\n"
  "\n"
  "stderr: the active effects and one progress line per stage (mesh,\n"
  "contact, material, assemble, solve, post, output), with the active-set\n"
  "history (iteration, residual, active multipliers, changed statuses), or\n"
  "with large deformation one solve line per load step (Newton iterations,\n"
  "residual, active multipliers, the monitor node).  stdout: the summary, one\n"
  "'name = value' per line.  Exit status: 0 success, 1 the run failed\n"
  "(message 'lac: ...' on stderr), 2 bad command line.\n"
  "\n"
  "MPI: mpirun -n N lac run SCENE runs on N processes, with the petsc\n"
  "strategy (auto takes it; a direct one asked for solves on process 0):\n"
  "process 0 reads the scene and the mesh, pairs, runs the active set and\n"
  "alone prints and writes the files; every process assembles the cells it\n"
  "owns, solves its rows and computes the stresses and errors of its\n"
  "cells.  The petsc strategy adds the summary lines processes,\n"
  "solver_iterations (Krylov, all solves) and solver_residual (true\n"
  "relative residual of the last).\n"
  "\n"
  "example: lac run chapters/01-problem/sphere-axi.scene --set level=1 \\\n"
  "           --set material.shell.E=3000\n";

/* Print "lac: message" on one line (newlines in the message become
 * blanks). */

typedef struct cmdline
{
  const char *scene;
  const char **set;     /* argc entries at most */
  size_t nset;
  const char *out;
  int quiet, timings, no_output, strategy;
  const char *petsc_options;
  double max_memory;
  char solver_set[64];
} cmdline;


static int
parse_run_args (int argc, char **argv, cmdline *c)
{
  for (int k = 2; k < argc; k++)
    {
      const char *v;
      int missing = 0;
      if ((v = lac_cli_option_value (argc, argv, &k, "--set", &missing)))
        c->set[c->nset++] = v;
      else if ((v = lac_cli_option_value (argc, argv, &k, "--solver", &missing)))
        {
          const lac_strategy_type *t =
            lac_strategy_type_of (lac_strategy_from_name (v));
          if (t && t->factor == LAC_FACTOR_NONE)  /* a type that factorizes */
            c->strategy = lac_strategy_from_name (v);   /* nothing: its own */
          else if (lac_solver_kind_from_name (v) < 0)      /* solver (petsc) */
            return lac_cli_usage_error (NULL, "--solver: expected dense, "
                                        "umfpack, cholmod or petsc, got", v);
          else
            {
              snprintf (c->solver_set, sizeof c->solver_set,
                        "scene.solver=%s", v);
              c->set[c->nset++] = c->solver_set;
            }
        }
      else if ((v = lac_cli_option_value (argc, argv, &k, "--strategy",
                                          &missing)))
        {
          if ((c->strategy = lac_strategy_from_name (v)) < 0)
            return lac_cli_usage_error (NULL, "--strategy: expected auto, "
                                        "dense, schur, augmented, split, "
                                        "saddle or petsc, got", v);
        }
      else if ((v = lac_cli_option_value (argc, argv, &k, "--petsc-options",
                                          &missing)))
        c->petsc_options = v;
      else if ((v = lac_cli_option_value (argc, argv, &k, "--out", &missing)))
        c->out = v;
      else if ((v = lac_cli_option_value (argc, argv, &k, "--max-memory",
                                          &missing)))
        {
          if (!lac_cli_max_memory (NULL, v, &c->max_memory))
            return LAC_CLI_USAGE;
        }
      else if (missing)
        return lac_cli_usage_error (NULL, "missing value after", argv[k]);
      else if (strcmp (argv[k], "--quiet") == 0)
        c->quiet = 1;
      else if (strcmp (argv[k], "--timings") == 0)
        c->timings = 1;
      else if (strcmp (argv[k], "--no-output") == 0)
        c->no_output = 1;
      else if (argv[k][0] == '-' && argv[k][1] != '\0')
        return lac_cli_usage_error (NULL, "unknown option", argv[k]);
      else if (c->scene)
        return lac_cli_usage_error (NULL, "more than one scene:",
                                    argv[k]);
      else
        c->scene = argv[k];
    }
  if (!c->scene)
    return lac_cli_usage_error (NULL, "run: no scene file given", NULL);
  return 0;
}

/* The strategy's fallback, if one happened in the solve stage. */
static void
print_fallback (const lac_run *r)
{
  const char *why = r->sol.newton
                    ? lac_strategy_fallback (r->sol.newton->strategy) : NULL;
  if (why)
    fprintf (stderr, "lac:       note: %s\n", why);
}

/* SIGINT and SIGTERM during the output stage: the stage stops between two
 * files and publishes nothing (io/lac_output_batch.h), then the process
 * ends by the signal.  A second signal ends it at once (the temporary
 * directory is then removed by the next run).  Outside the output stage
 * the signals keep their default action: no file of the run exists yet. */
static volatile sig_atomic_t stop_signal;

static void
on_stop (int sig)
{
  if (stop_signal)                          /* a second one: at once */
    {
      signal (sig, SIG_DFL);
      raise (sig);
    }
  stop_signal = sig;
}

/* on: catch SIGINT and SIGTERM, unless lac was started with them ignored
 * (a background job of a shell script): then they stay ignored.  off: back
 * to what lac was started with. */
static void
catch_stop (int on)
{
  static const int sig[2] = { SIGINT, SIGTERM };
  static struct sigaction initial[2];
  static int saved;
  for (int k = 0; k < 2; k++)
    {
      struct sigaction sa;
      if (!saved && sigaction (sig[k], NULL, &initial[k]) != 0)
        return;
      sa = initial[k];
      if (on && initial[k].sa_handler != SIG_IGN)
        {
          memset (&sa, 0, sizeof sa);
          sa.sa_handler = on_stop;
          sigemptyset (&sa.sa_mask);
        }
      sigaction (sig[k], &sa, NULL);
    }
  saved = 1;
}


/* A failure found here, "SCENE: what; the outputs" on one line. */
static int
fail_here (const lac_run *r, const char *what, int e)
{
  char msg[512];
  snprintf (msg, sizeof msg, "%s: %s (%s)%s%s%s", r->scene->path, what,
            strerror (e), r->opts.no_output ? "" : "; nothing was published:"
            " the files in '", r->opts.no_output ? "" : r->out_dir,
            r->opts.no_output ? "" : "' are those of the earlier run");
  lac_cli_print_error (msg);
  return LAC_EIO;
}

/* The summary on stdout, flushed and checked before the files are
 * published: a pipe whose reader is gone (EPIPE: SIGPIPE is ignored), a
 * full disk, a stdout that cannot be written, or a progress line that
 * stderr did not take, is a failed run that leaves the earlier files. */
static int
print_summary (const lac_run *r)
{
  errno = 0;
  for (size_t k = 0; k < r->res.summary.n; k++)
    printf ("%s = %s\n", r->res.summary.key[k], r->res.summary.val[k]);
  if (fflush (stdout) != 0 || ferror (stdout))
    return fail_here (r, "cannot write the summary to stdout",
                      errno ? errno : EIO);
  if (ferror (stderr))
    return fail_here (r, "cannot write the progress lines to stderr", EIO);
  return LAC_SUCCESS;
}

/* Run the stages, reporting each; a progress line that stderr did not
 * take stops the run (its files could not be published anyway). */
static int
run_stages (const cmdline *c, lac_run *r)
{
  int status;
  do
    {
      int stage = r->stage;
      catch_stop (stage >= LAC_STAGE_OUTPUT);
      status = lac_run_iterate (r);
      if (!c->quiet && (status == LAC_CONTINUE || status == LAC_SUCCESS))
        {
          fprintf (stderr, "lac: [%d/%d] %-9s %s (%.2f s)\n", stage + 1,
                   LAC_NSTAGES, lac_run_stage_name (stage), r->progress,
                   r->time[stage]);
          if (stage == LAC_STAGE_SOLVE && r->stage != stage)
            print_fallback (r);
          if (ferror (stderr))
            return fail_here (r, "cannot write the progress lines to "
                              "stderr", EIO);
        }
    }
  while (status == LAC_CONTINUE);
  if (status != LAC_SUCCESS)
    lac_cli_print_failure (r->scene->path, status);
  return status;
}

/* What can be checked before a run about its output directory. */
static int
check_output (const lac_run *r)
{
  char msg[700];
  int status;
  if (r->opts.no_output || !(status = lac_output_batch_check (r->out_dir)))
    return LAC_SUCCESS;
  lac_run_inner_message (msg, sizeof msg);
  lac_error_set (status, r->scene->path, "%s", msg);
  lac_cli_print_failure (r->scene->path, status);
  return status;
}

/* The effects, and the MPI processes if more than one. */
static void
print_start (const lac_scene *sc, const lac_run *r)
{
  int rank, size;
  fprintf (stderr, "lac: %s: %s\nlac: effects:", sc->path, sc->scene.title);
  for (size_t k = 0; k < r->neffects; k++)
    fprintf (stderr, "%s %s", k ? "," : "", r->effects[k]);
  fprintf (stderr, "\n");
  lac_petsc_rank (&rank, &size);
  if (size > 1)
    fprintf (stderr, "lac: %d MPI processes: process 0 reads, pairs and "
             "writes; the petsc strategy assembles, solves and computes the "
             "stresses on all %d\n", size, size);
}

/* 1. read the scene; 2. run the stages, reporting each; 3. print the
 * summary; 4. publish the files, last, when nothing else can fail. */
static int
cmd_run (const cmdline *c)
{
  lac_scene *sc = NULL;
  lac_run *r = NULL;
  lac_run_opts opts = { c->out, c->timings, c->no_output, c->strategy,
                        c->max_memory, &stop_signal, 0, 0 };
  int status;

  /* 1. The scene, with the overrides. */
  status = lac_scene_read (c->scene, c->nset, c->set, &sc);
  if (status)
    {
      lac_cli_print_failure (c->scene, status);
      return LAC_CLI_FAILURE;
    }
  if (!(r = lac_run_alloc (sc, &opts)))
    {
      lac_cli_print_failure (sc->path, LAC_ENOMEM);
      lac_scene_free (sc);
      return LAC_CLI_FAILURE;
    }
  lac_run_hold_files (r);
  if (!c->quiet)
    print_start (sc, r);

  /* 2. The stages; 3. the summary; 4. the files. */
  status = check_output (r);
  if (!status)
    status = run_stages (c, r);
  if (!status)
    status = print_summary (r);
  if (!status && (status = lac_run_publish (r)))
    lac_cli_print_failure (r->scene->path, status);
  lac_run_free (r);
  lac_scene_free (sc);
  catch_stop (0);
  if (stop_signal && status != LAC_SUCCESS)  /* end as the signal asked */
    raise (stop_signal);
  return status == LAC_SUCCESS ? EXIT_SUCCESS : LAC_CLI_FAILURE;
}

/* Before lac run opens any file: a closed stdin or stderr gets /dev/null
 * opened read-only in its place, so that no file of the run becomes fd 0
 * or 2 (messages would be written into it) and writes to it fail (seen at
 * the end); a closed stdout likewise, and then the run is refused at once:
 * its summary would be lost.  A reader of stdout that goes away makes
 * writes fail with EPIPE (SIGPIPE ignored) instead of killing lac, maybe
 * after the files were published. */
static int
prepare_streams (void)
{
  int closed_stdout = 0;
  for (int fd = 0; fd < 3; fd++)
    if (fcntl (fd, F_GETFD) < 0 && errno == EBADF)
      {
        int n = open ("/dev/null", O_RDONLY);   /* the lowest free: fd */
        if (n >= 0 && n != fd)
          {
            dup2 (n, fd);
            close (n);
          }
        closed_stdout |= fd == 1;
      }
  signal (SIGPIPE, SIG_IGN);
  if (closed_stdout)
    {
      lac_cli_print_error ("stdout is closed: the summary of the run would "
                           "be lost (>/dev/null discards it)");
      return LAC_CLI_FAILURE;
    }
  return EXIT_SUCCESS;
}

/* After a run: the PETSc options that nothing read (a wrong prefix, or a
 * run that solved nothing with PETSc) are named on stderr. */
static void
warn_unused_options (void)
{
  char names[512];
  int n = lac_petsc_options_unused (names, sizeof names);
  if (n > 0)
    fprintf (stderr, "lac: warning: %d PETSc option%s never read: %s "
             "(they are read by the petsc strategy only; lac --help, "
             "--petsc-options, says which prefix)\n",
             n, n > 1 ? "s were" : " was", names);
}

/* The number of processes an MPI launcher started (Open MPI, MPICH),
 * 1 without one. */
static int
launched_processes (void)
{
  const char *v = getenv ("OMPI_COMM_WORLD_SIZE");
  if (!v)
    v = getenv ("PMI_SIZE");
  return v ? atoi (v) : 1;
}

/* MPI and PETSc, when the run needs them: a strategy whose type solves
 * on the MPI processes, PETSc options, or a launcher's processes
 * (lac_petsc_initialize fails with the install line in a build without
 * PETSc).  *rank: this process. */
static int
start_processes (const cmdline *c, int *rank)
{
  const lac_strategy_type *t = lac_strategy_type_of (c->strategy);
  int size;
  *rank = 0;
  if (!(t && t->processes) && !c->petsc_options
      && launched_processes () <= 1)
    return EXIT_SUCCESS;
  if (lac_petsc_initialize (c->petsc_options))
    {
      lac_cli_print_error (lac_error_message ());
      return LAC_CLI_FAILURE;
    }
  lac_petsc_rank (rank, &size);
  return EXIT_SUCCESS;
}

/* Processes 1 .. N-1: serve the petsc strategy of process 0. */
static int
serve (void)
{
  if (lac_petsc_serve () == LAC_SUCCESS)
    return EXIT_SUCCESS;
  lac_cli_print_error (lac_error_message ());
  return LAC_CLI_FAILURE;
}

/* lac --help, lac --version, lac CMD --help: nothing to compute. */
static int
asks_help (int argc, char **argv)
{
  for (int k = 1; k < argc; k++)
    if (!strcmp (argv[k], "--help") || !strcmp (argv[k], "-h"))
      return 1;
  return argc == 2 && !strcmp (argv[1], "--version");
}

int
main (int argc, char **argv)
{
  cmdline c;
  int ret;
  lac_cli_fit_openblas (argv);     /* OpenBLAS's kernels and spin */
  if (lac_cli_fit_limits (argv, !asks_help (argc, argv)))  /* ulimit -v */
    {
      fflush (stderr);
      _exit (LAC_CLI_FAILURE);     /* exit () may wait for a stuck thread */
    }
  if (argc < 2)
    return lac_cli_usage_error (NULL, "no command", NULL);
  /* The other subcommands parse their own arguments (and --help). */
  if (strcmp (argv[1], "infsup") == 0 || strcmp (argv[1], "render") == 0)
    {
      signal (SIGPIPE, SIG_IGN);   /* a reader gone: EPIPE, a message */
      lac_init ();
      ret = argv[1][0] == 'i' ? lac_cli_infsup (argc - 1, argv + 1)
                              : lac_cli_render (argc - 1, argv + 1);
      lac_finalize ();
      return ret;
    }
  for (int k = 1; k < argc; k++)
    if (strcmp (argv[k], "--help") == 0 || strcmp (argv[k], "-h") == 0)
      {
        fputs (help_text, stdout);
        printf ("\n%s\n%s", lac_cli_infsup_help, lac_cli_render_help);
        return EXIT_SUCCESS;
      }
  if (strcmp (argv[1], "--version") == 0)
    {
      const char *blas = lac_cli_blas_config ();
      printf ("lac %s\n", LAC_VERSION);
      const char *spin = getenv ("OPENBLAS_THREAD_TIMEOUT");
      if (blas)                  /* the kernels the numbers come from */
        printf ("BLAS: %s\n", blas);
      if (blas && spin)          /* lac_cli_openblas.h */
        printf ("BLAS idle threads: spin 2^%s cycles\n", spin);
      return EXIT_SUCCESS;
    }
  if (strcmp (argv[1], "run") != 0)
    return lac_cli_usage_error (NULL, "unknown command", argv[1]);
  if (prepare_streams () != EXIT_SUCCESS)
    return LAC_CLI_FAILURE;
  memset (&c, 0, sizeof c);
  if (!(c.set = malloc ((size_t) argc * sizeof *c.set)))
    {
      lac_cli_print_error ("out of memory");
      return LAC_CLI_FAILURE;
    }
  if ((ret = parse_run_args (argc, argv, &c)) == 0)
    {
      int rank;
      lac_init ();
      if ((ret = start_processes (&c, &rank)) == EXIT_SUCCESS)
        ret = rank == 0 ? cmd_run (&c) : serve ();
      if (ret == EXIT_SUCCESS && rank == 0)
        warn_unused_options ();
      lac_petsc_finalize ();
      lac_finalize ();
    }
  free (c.set);
  return ret;
}
