/* Dense LU with partial pivoting for the compiled BDF step loop (cbdf.c).

   As acausal.solvers.linalg does with LAPACK: a factorization whose smallest pivot is
   below 64 eps of the largest is judged again on the equilibrated matrix (every row,
   then every column scaled to a largest magnitude of one, as LAPACK's xGEEQU), since a
   small pivot may only reflect the units of the equations and variables.  Matrices are
   row-major n x n. */
#include <math.h>
#include "cbdf.h"
#include <string.h>
#include <float.h>

enum { LU_OK = 0, LU_SINGULAR = 4, LU_NONFINITE = 5 };   /* as F_SINGULAR/F_NONFINITE */

static int lu_factor(double *A, int64_t *piv, int64_t n, double *dmin, double *dmax) {
  *dmin = INFINITY; *dmax = 0.0;
  for (int64_t k = 0; k < n; ++k) {
    int64_t p = k; double big = fabs(A[k * n + k]);
    for (int64_t i = k + 1; i < n; ++i) {
      double a = fabs(A[i * n + k]);
      if (a > big) { big = a; p = i; }
    }
    piv[k] = p;
    if (p != k)
      for (int64_t j = 0; j < n; ++j) {
        double s = A[k * n + j]; A[k * n + j] = A[p * n + j]; A[p * n + j] = s;
      }
    double d = A[k * n + k];
    if (fabs(d) < *dmin) *dmin = fabs(d);
    if (fabs(d) > *dmax) *dmax = fabs(d);
    if (d == 0.0) return 1;
    double inv = 1.0 / d;
    for (int64_t i = k + 1; i < n; ++i) {
      double l = A[i * n + k] * inv;
      A[i * n + k] = l;
      if (l != 0.0) {
        double *ri = A + i * n, *rk = A + k * n;
        for (int64_t j = k + 1; j < n; ++j) ri[j] -= l * rk[j];
      }
    }
  }
  return 0;
}

static int pivots_ok(double dmin, double dmax) {
  return dmax > 0.0 && dmin > 64.0 * DBL_EPSILON * dmax;
}

/* LU of J into A (J kept); r, c: the equilibration, used when *equil is set */
int dense_factor(const double *J, double *A, int64_t *piv, double *r, double *c,
                 int64_t n, int *equil) {
  double dmin, dmax;
  *equil = 0;
  for (int64_t i = 0; i < n * n; ++i) if (!isfinite(J[i])) return LU_NONFINITE;
  memcpy(A, J, sizeof(double) * n * n);
  if (!lu_factor(A, piv, n, &dmin, &dmax) && pivots_ok(dmin, dmax)) return LU_OK;
  for (int64_t i = 0; i < n; ++i) {
    double a = 0.0;
    for (int64_t j = 0; j < n; ++j) if (fabs(J[i * n + j]) > a) a = fabs(J[i * n + j]);
    r[i] = 1.0 / (a > 1e-300 ? a : 1e-300);
  }
  for (int64_t j = 0; j < n; ++j) {
    double a = 0.0;
    for (int64_t i = 0; i < n; ++i) { double b = fabs(J[i * n + j]) * r[i]; if (b > a) a = b; }
    c[j] = 1.0 / (a > 1e-300 ? a : 1e-300);
  }
  for (int64_t i = 0; i < n; ++i)
    for (int64_t j = 0; j < n; ++j) A[i * n + j] = J[i * n + j] * r[i] * c[j];
  if (lu_factor(A, piv, n, &dmin, &dmax) || !pivots_ok(dmin, dmax)) return LU_SINGULAR;
  *equil = 1;
  return LU_OK;
}

/* b := J^{-1} b; r (NULL: not equilibrated) and c as returned by dense_factor */
void dense_solve(const double *A, const int64_t *piv, const double *r, const double *c,
                 int64_t n, double *b) {
  if (r) for (int64_t i = 0; i < n; ++i) b[i] *= r[i];
  for (int64_t k = 0; k < n; ++k)
    if (piv[k] != k) { double s = b[k]; b[k] = b[piv[k]]; b[piv[k]] = s; }
  for (int64_t i = 1; i < n; ++i) {
    double s = b[i]; const double *ri = A + i * n;
    for (int64_t j = 0; j < i; ++j) s -= ri[j] * b[j];
    b[i] = s;
  }
  for (int64_t i = n - 1; i >= 0; --i) {
    double s = b[i]; const double *ri = A + i * n;
    for (int64_t j = i + 1; j < n; ++j) s -= ri[j] * b[j];
    b[i] = s / ri[i];
  }
  if (r) for (int64_t i = 0; i < n; ++i) b[i] *= c[i];
}
