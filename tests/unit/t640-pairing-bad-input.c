/* t640: bad input to the pairing: empty lists, surfaces that do not face
 * each other or are apart, mismatched meshes, bad facets and options, and
 * failing allocations: a clear status and message, never a silent zero
 * [LAC §4.6] */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "base/lac_mem.h"
#include "contact/lac_pairing.h"
#include "base/lac_status.h"
#include "unit/t6-pairing-mesh.h"

/* Slave: 4 x 4 tri3 on the unit square (normal +z); master: 3 x 3 quad4
 * at height z (normal sm). */
static lac_mesh *
build (double z, double sm, pm_side *ss, pm_side *ms)
{
  double zs[2] = { 0, 1 }, zm[2] = { z, sm };
  pm_builder B;
  pm_surf a, b;
  pm_builder_init (&B, 3);
  pm_grid (&a, 0, 1, 4, 4, 0, 0.2, 1);
  pm_grid (&b, 0, 1, 3, 3, 0, 0, 0);
  *ss = pm_add_side (&B, &a, LAC_TRI3, pm_flat3, zs, 0.05);
  *ms = pm_add_side (&B, &b, LAC_QUAD4, pm_flat3, zm, 0.05);
  lac_mesh *m = pm_finish (&B);
  pm_surf_free (&a), pm_surf_free (&b);
  pm_builder_free (&B);
  return m;
}

int
main (void)
{
  pm_side ss, ms;
  lac_pairing *P = NULL;
  lac_pairing_opts o;
  lac_init ();

  /* 1. Empty lists, missing mesh. */
  lac_mesh *m = build (0, -1, &ss, &ms);
  lac_pairing_facets fs = pm_facets (m, &ss), fm = pm_facets (m, &ms);
  lac_pairing_facets e = fs;
  e.n = 0;
  check_status (lac_pairing_build (&e, &fm, NULL, &P), LAC_EINVAL, "empty slave");
  check_message ("slave facet list is empty", "empty slave: message");
  check_true (P == NULL, "empty slave: no result");
  e = fm, e.n = 0;
  check_status (lac_pairing_build (&fs, &e, NULL, &P), LAC_EINVAL, "empty master");
  check_message ("master facet list is empty", "empty master: message");
  e = fs, e.mesh = NULL;
  check_status (lac_pairing_build (&e, &fm, NULL, &P), LAC_EINVAL, "no mesh");
  check_message ("no slave facet list", "no mesh: message");

  /* 2. Bad facets and options. */
  int badface[16];
  for (int i = 0; i < 16; i++)
    badface[i] = ss.face[i];
  badface[3] = 7;
  e = fs, e.face = badface;
  check_status (lac_pairing_build (&e, &fm, NULL, &P), LAC_EINVAL, "bad face");
  check_message ("slave facet 3", "bad face: message names the facet");
  lac_pairing_opts_init (&o);
  o.degree = 99;
  check_status (lac_pairing_build (&fs, &fm, &o, &P), LAC_EINVAL, "degree 99");
  check_message ("degree 99", "degree 99: message");
  lac_pairing_opts_init (&o);
  o.dist_rel = -1;
  check_status (lac_pairing_build (&fs, &fm, &o, &P), LAC_EINVAL, "dist_rel < 0");
  check_message ("bad options", "dist_rel < 0: message");

  /* 3. Memory failures: every allocation in turn, until the build succeeds;
   *    each failure is LAC_ENOMEM with a message and no leak (ASan). */
  long k, n_fail = 0;
  for (k = 0; k < 1000; k++)
    {
      lac_mem_fail_after (k);
      int status = lac_pairing_build (&fs, &fm, NULL, &P);
      lac_mem_fail_after (-1);
      if (status == LAC_SUCCESS)
        break;
      n_fail++;
      check_status (status, LAC_ENOMEM, "allocation %ld fails", k);
      check_true (P == NULL, "allocation %ld fails: no result", k);
    }
  check_true (P != NULL && n_fail > 10, "memory failures: %ld, then success",
              n_fail);
  if (P)
    check_rel (lac_pairing_total (P), 1, 1e-12, "after memory failures");
  lac_pairing_free (P), P = NULL;
  lac_mesh_free (m), pm_side_free (&ss), pm_side_free (&ms);

  /* 4. Slave and master with the same orientation (not facing). */
  m = build (0, 1, &ss, &ms);
  fs = pm_facets (m, &ss), fm = pm_facets (m, &ms);
  check_status (lac_pairing_build (&fs, &fm, NULL, &P), LAC_EINVAL,
                "same orientation");
  check_message ("faces it", "same orientation: message");
  check_true (P == NULL, "same orientation: no result");
  lac_mesh_free (m), pm_side_free (&ss), pm_side_free (&ms);

  /* 5. Facing, but 2 units apart (facets ~0.3): beyond the gap bound. */
  m = build (2, -1, &ss, &ms);
  fs = pm_facets (m, &ss), fm = pm_facets (m, &ms);
  check_status (lac_pairing_build (&fs, &fm, NULL, &P), LAC_EINVAL, "apart");
  check_message ("gap bound", "apart: message");
  lac_pairing_opts_init (&o);
  o.allow_empty = 1;                    /* separated bodies: a valid result */
  check_status (lac_pairing_build (&fs, &fm, &o, &P), LAC_SUCCESS,
                "apart, allow_empty");
  if (P)
    {
      check_int ((long) P->npairs, 0, "apart, allow_empty: no pair");
      check_abs (lac_pairing_total (P), 0, 0, "apart, allow_empty: total");
      check_true (P->measure[0] > 0, "apart, allow_empty: measures");
    }
  lac_pairing_free (P), P = NULL;
  o.allow_empty = 0;
  o.dist_abs = 2.5;                     /* an initial gap the scene allows */
  check_status (lac_pairing_build (&fs, &fm, &o, &P), LAC_SUCCESS,
                "apart, dist_abs 2.5");
  if (P)
    check_rel (P->gap[0], 2, 1e-13, "apart, dist_abs 2.5: gap");
  lac_pairing_free (P), P = NULL;

  /* 6. Invalid facets: a non-convex quadrangle (from an inverted cell), a
   *    triangle with no area. */
  {
    double zs[2] = { 0, 1 };
    double quad[8] = { 0, 0, 1, 0, 0.2, 0.2, 0, 1 }, tri[6] = { 0, 0, 1, 0, 2, 0 };
    pm_builder B;
    pm_surf q, t;
    pm_builder_init (&B, 3);
    pm_surf_alloc (&q, 2, 4, 1);
    pm_surf_alloc (&t, 2, 3, 1);
    memcpy (q.p, quad, sizeof quad), memcpy (t.p, tri, sizeof tri);
    for (int a = 0; a < 4; a++)
      q.fv[a] = a, t.fv[a] = a < 3 ? a : -1;
    pm_side sq = pm_add_side (&B, &q, LAC_QUAD4, pm_flat3, zs, 0.1);
    pm_side st = pm_add_side (&B, &t, LAC_TRI3, pm_flat3, zs, 0.1);
    lac_mesh *mi = pm_finish (&B);
    lac_pairing_facets fq = pm_facets (mi, &sq), ft = pm_facets (mi, &st);
    check_status (lac_pairing_build (&fq, &fm, NULL, &P), LAC_ESING,
                  "non-convex quad4");
    check_message ("not a convex quadrangle", "non-convex quad4: message");
    check_message ("slave facet 0", "non-convex quad4: message names it");
    check_status (lac_pairing_build (&ft, &fm, NULL, &P), LAC_ESING,
                  "flat triangle");
    check_message ("degenerate tri3", "flat triangle: message");
    lac_mesh_free (mi), pm_side_free (&sq), pm_side_free (&st);
    pm_surf_free (&q), pm_surf_free (&t), pm_builder_free (&B);
  }

  /* 7. Slave and master of different dimensions. */
  pm_builder B;
  pm_surf l;
  double fl[2] = { 0, 1 };
  pm_builder_init (&B, 2);
  pm_line (&l, 0, 1, 4, 0);
  pm_side s2 = pm_add_side (&B, &l, LAC_SEG2, pm_flat2, fl, 0.1);
  lac_mesh *m2 = pm_finish (&B);
  lac_pairing_facets f2 = pm_facets (m2, &s2);
  check_status (lac_pairing_build (&f2, &fm, NULL, &P), LAC_EINVAL,
                "2D slave, 3D master");
  check_message ("2-D", "2D slave, 3D master: message");
  lac_mesh_free (m2), pm_side_free (&s2), pm_surf_free (&l);
  pm_builder_free (&B);
  lac_mesh_free (m), pm_side_free (&ss), pm_side_free (&ms);
  return check_summary ();
}
