/* Dynamic state selection in the compiled BDF step loop (cbdf.c): the test, after every
   accepted step, of whether the current dummy derivatives are still good enough.

   acausal.runtime.dynamic keeps the current choice without searching as long as, on every
   level of the dynamic state sets, its quality -- |det| of the chosen columns of the
   scaled level block over the product of the block's row norms -- is at least a fraction
   of the best quality found at the last search.  This file evaluates exactly that test on
   the generated Jacobian's values at each accepted point (dyn_due, called by cbdf_run
   after every step); only when it fails does the loop return, and Python
   searches (and may still keep the choice, by hysteresis).  The choice is fixed during a
   run of the loop, so everything about it (which Jacobian entries form each block, the
   column scales, the chosen columns, the thresholds) is laid out once by Python
   (acausal.solvers.cbdf_dyn):

     dl (int64_t):   [0] levels, [1] 1 when the choice must be re-examined (output),
                  [2] 1 when no test is possible (Python examines after every step),
                  [3] offset of the work area in dd, then per level
                  nr, nc, keep[nr] (chosen columns), entry[nr * nc] (index into the
                  Jacobian values, -1 for a structural zero)
     dd (double): per level the threshold and scale[nc]; then the work area
                  (nr * nc + nr * nr doubles of the largest level). */
#include <math.h>
#include "cbdf.h"

/* |det| of the row-major k x k matrix A (destroyed): LU with partial pivoting */
static double dyn_absdet(double *A, int64_t k) {
  double det = 1.0;
  for (int64_t j = 0; j < k; ++j) {
    int64_t p = j; double big = fabs(A[j * k + j]);
    for (int64_t i = j + 1; i < k; ++i)
      if (fabs(A[i * k + j]) > big) { big = fabs(A[i * k + j]); p = i; }
    if (big == 0.0) return 0.0;
    if (p != j)
      for (int64_t c = 0; c < k; ++c) {
        double s = A[j * k + c]; A[j * k + c] = A[p * k + c]; A[p * k + c] = s;
      }
    double d = A[j * k + j];
    det *= d;
    for (int64_t i = j + 1; i < k; ++i) {
      double f = A[i * k + j] / d;
      for (int64_t c = j + 1; c < k; ++c) A[i * k + c] -= f * A[j * k + c];
    }
  }
  return fabs(det);
}

/* 1 when the current choice is kept without a search, 0 when Python must look again;
   vals: the Jacobian values (nv of them) at the accepted point */
int dyn_keeps(const double *vals, int64_t nv, const int64_t *dl, double *dd) {
  if (dl[2]) return 0;
  for (int64_t e = 0; e < nv; ++e)
    if (!isfinite(vals[e])) return 1;     /* as Python: an unusable point changes nothing */
  double *B = dd + dl[3];
  const int64_t *lp = dl + 4;
  const double *dp = dd;
  for (int64_t lev = 0; lev < dl[0]; ++lev) {
    int64_t nr = lp[0], nc = lp[1];
    const int64_t *keep = lp + 2, *entry = lp + 2 + nr;
    double threshold = dp[0];
    const double *scale = dp + 1;
    double *S = B + nr * nc, norms = 1.0;
    for (int64_t i = 0; i < nr; ++i) {
      double peak = 0.0, ss = 0.0, *row = B + i * nc;
      for (int64_t j = 0; j < nc; ++j) {
        int64_t k = entry[i * nc + j];
        row[j] = k >= 0 ? vals[k] * scale[j] : 0.0;
        if (fabs(row[j]) > peak) peak = fabs(row[j]);
      }
      if (peak > 0) for (int64_t j = 0; j < nc; ++j) row[j] /= peak;
      for (int64_t j = 0; j < nc; ++j) ss += row[j] * row[j];
      norms *= sqrt(ss);
      for (int64_t j = 0; j < nr; ++j) S[i * nr + j] = row[keep[j]];
    }
    double quality = norms > 0 ? dyn_absdet(S, nr) / norms : 0.0;
    if (!(quality >= threshold)) return 0;
    lp += 2 + nr + nr * nc;
    dp += 1 + nc;
  }
  return 1;
}

/* 1 when Python must re-examine the choice of states at the accepted point (t, y),
   also left in dl[1]; jac: the generated Jacobian (NULL when the problem's functions
   are Python: then Python examines after every step) */
int dyn_due(int64_t *dl, double *dd, void *jac, double t, const double *y,
            const double *p, const double *m, double *vals, double *w, int64_t nv) {
  int keep = 0;
  if (!dl[2] && jac) {
    ((cbdf_genfn)jac)(t, y, p, m, vals, w);
    keep = dyn_keeps(vals, nv, dl, dd);
  }
  dl[1] = !keep;
  return !keep;
}
