/* Sparse LU for the compiled BDF step loop (cbdf.c) on systems too large for dense LU.

   Left-looking LU with threshold partial pivoting, column by column (Gilbert & Peierls
   1988; the formulation of Davis, "Direct Methods for Sparse Linear Systems", SIAM 2006,
   ch. 6, and of KLU, Davis & Palamadai Natarajan 2010): column k of P A Q is obtained
   by a sparse triangular solve with the columns of L found so far, whose nonzero
   pattern is the set of rows reachable from the column's entries in the graph of L
   (a depth-first search), so each factorization costs time proportional to the
   floating-point work, not to n^2.

   The iteration matrix dF/dy + cj dF/dy' keeps its pattern for the whole run and
   changes its values only a little from one factorization to the next, so the
   expensive choices are made once, by SuperLU (scipy.sparse.linalg.splu, called from
   cbdf_sparse.py on the first matrix): the fill-reducing column order Q (COLAMD) and
   the pivot row of every step.  Each factorization here follows that order and takes
   SuperLU's pivot row while it is at least PIVOT_TOL of the largest candidate in its
   column (the usual threshold test, as KLU's refactorization falls back to pivoting
   when a kept pivot becomes small); otherwise it pivots on the largest one, and the
   storage grows as needed.  A factorization whose pivots look singular (below 64 eps
   of the largest) is judged again on the equilibrated matrix, exactly as the dense LU
   of cbdf_lu.c and acausal.solvers.linalg do.

   The matrix is CSC with a fixed pattern (Ap, Ai); its values are assembled in place
   from the generated Jacobian's entries through a slot map (sparse_jacobian). */
#include <math.h>
#include "cbdf.h"
#include <stdlib.h>
#include <string.h>
#include <float.h>

#define PIVOT_TOL 0.1

typedef struct {
  int64_t n, nnz, nslot;
  int64_t *Ap, *Ai, *slot;        /* the pattern, and each Jacobian entry's place in Ax */
  double *Ax, *Bx;             /* the values; Bx: equilibrated copy */
  int64_t *q, *pref;              /* step k: column q[k], preferred pivot row pref[k] */
  int64_t *Lp, *Li, *Up, *Ui, lcap, ucap;   /* L (unit diagonal first), U (no diagonal) */
  double *Lx, *Ux, *Ud;
  int64_t *pinv, *prow;           /* step of row i (-1: not yet), row of step k */
  int64_t *xi, *stack, *pos, *mark;   /* depth-first search */
  double *x, *r, *c, *w;       /* work column, equilibration, solve work */
  int equil, ok;
} sparse_lu;

void sparse_free(void *h) {
  sparse_lu *s = (sparse_lu *)h;
  if (!s) return;
  void *ptrs[] = {s->Ap, s->Ai, s->slot, s->Ax, s->Bx, s->q, s->pref, s->Lp, s->Li,
                  s->Up, s->Ui, s->Lx, s->Ux, s->Ud, s->pinv, s->prow, s->xi, s->stack,
                  s->pos, s->mark, s->x, s->r, s->c, s->w};
  for (size_t k = 0; k < sizeof(ptrs) / sizeof(ptrs[0]); ++k) free(ptrs[k]);
  free(s);
}

static void *copy_of(const void *src, size_t bytes) {
  void *d = malloc(bytes ? bytes : 1);
  if (d && src) memcpy(d, src, bytes);
  return d;
}

/* the pattern (CSC, n x n), the slot of each Jacobian entry, the column order q and
   preferred pivot rows pref (-1: none) of the analysis; cap: first guess of nnz(L+U) */
void *sparse_new(int64_t n, const int64_t *Ap, const int64_t *Ai, int64_t nslot,
                 const int64_t *slot, const int64_t *q, const int64_t *pref, int64_t cap) {
  sparse_lu *s = (sparse_lu *)calloc(1, sizeof(sparse_lu));
  if (!s) return 0;
  int64_t nnz = Ap[n];
  s->n = n; s->nnz = nnz; s->nslot = nslot;
  s->Ap = copy_of(Ap, sizeof(int64_t) * (n + 1));
  s->Ai = copy_of(Ai, sizeof(int64_t) * nnz);
  s->slot = copy_of(slot, sizeof(int64_t) * nslot);
  s->q = copy_of(q, sizeof(int64_t) * n);
  s->pref = copy_of(pref, sizeof(int64_t) * n);
  s->Ax = calloc(nnz ? nnz : 1, sizeof(double));
  s->Bx = calloc(nnz ? nnz : 1, sizeof(double));
  s->lcap = s->ucap = (cap > 2 * n ? cap : 2 * n) + n;
  s->Lp = malloc(sizeof(int64_t) * (n + 1)); s->Up = malloc(sizeof(int64_t) * (n + 1));
  s->Li = malloc(sizeof(int64_t) * s->lcap); s->Lx = malloc(sizeof(double) * s->lcap);
  s->Ui = malloc(sizeof(int64_t) * s->ucap); s->Ux = malloc(sizeof(double) * s->ucap);
  s->Ud = malloc(sizeof(double) * (n ? n : 1));
  s->pinv = malloc(sizeof(int64_t) * (n ? n : 1)); s->prow = malloc(sizeof(int64_t) * (n ? n : 1));
  s->xi = malloc(sizeof(int64_t) * (n ? n : 1)); s->stack = malloc(sizeof(int64_t) * (n ? n : 1));
  s->pos = malloc(sizeof(int64_t) * (n ? n : 1)); s->mark = calloc(n ? n : 1, sizeof(int64_t));
  s->x = calloc(n ? n : 1, sizeof(double)); s->w = malloc(sizeof(double) * (n ? n : 1));
  s->r = malloc(sizeof(double) * (n ? n : 1)); s->c = malloc(sizeof(double) * (n ? n : 1));
  if (!s->Ap || !s->Ai || !s->slot || !s->q || !s->pref || !s->Ax || !s->Bx || !s->Lp ||
      !s->Up || !s->Li || !s->Lx || !s->Ui || !s->Ux || !s->Ud || !s->pinv || !s->prow ||
      !s->xi || !s->stack || !s->pos || !s->mark || !s->x || !s->w || !s->r || !s->c) {
    sparse_free(s);
    return 0;
  }
  return s;
}

double *sparse_values(void *h) { return ((sparse_lu *)h)->Ax; }

/* Ax from the generated Jacobian's entries v (signs js), then cj on the rows
   der(s) - f(s) of the nsz states, cj and -1 on the nl linking rows, in the order of
   the problem's jac_pattern */
void sparse_jacobian(void *h, const double *v, const double *js, int64_t njac, int64_t nsz,
                     int64_t nl, double cj) {
  sparse_lu *s = (sparse_lu *)h;
  const int64_t *sl = s->slot;
  memset(s->Ax, 0, sizeof(double) * s->nnz);
  for (int64_t e = 0; e < njac; ++e) s->Ax[sl[e]] += js[e] * v[e];
  sl += njac;
  for (int64_t i = 0; i < nsz + nl; ++i) s->Ax[sl[i]] += cj;
  sl += nsz + nl;
  for (int64_t i = 0; i < nl; ++i) s->Ax[sl[i]] -= 1.0;
}

static int grow(int64_t **idx, double **val, int64_t *cap, int64_t need) {
  if (need <= *cap) return 1;
  int64_t nc = 2 * *cap > need ? 2 * *cap : need;
  int64_t *i2 = realloc(*idx, sizeof(int64_t) * nc);
  if (!i2) return 0;
  *idx = i2;
  double *v2 = realloc(*val, sizeof(double) * nc);
  if (!v2) return 0;
  *val = v2; *cap = nc;
  return 1;
}

/* rows reachable from the entries of column col of A in the graph of L (rows already
   pivoted lead on to their L column): xi[top..n-1] in topological order */
static int64_t reach(sparse_lu *s, int64_t col, int64_t stamp) {
  int64_t n = s->n, top = n, *mark = s->mark, *stack = s->stack, *pos = s->pos,
       *pinv = s->pinv, *Lp = s->Lp, *Li = s->Li;
  for (int64_t p = s->Ap[col]; p < s->Ap[col + 1]; ++p) {
    int64_t start = s->Ai[p];
    if (mark[start] == stamp) continue;
    int64_t head = 0;
    stack[0] = start;
    while (head >= 0) {
      int64_t i = stack[head], J = pinv[i];
      if (mark[i] != stamp) {
        mark[i] = stamp;
        pos[head] = J < 0 ? 0 : Lp[J] + 1;     /* skip L's unit diagonal */
      }
      int done = 1;
      if (J >= 0) {
        int64_t end = Lp[J + 1];
        for (int64_t p2 = pos[head]; p2 < end; ++p2) {
          int64_t child = Li[p2];
          if (mark[child] == stamp) continue;
          pos[head] = p2 + 1;
          stack[++head] = child;
          done = 0;
          break;
        }
      }
      if (done) { --head; s->xi[--top] = i; }
    }
  }
  return top;
}

/* LU of the values vals: LU_OK, or LU_SINGULAR when a column has no usable pivot */
static int lu_numeric(sparse_lu *s, const double *vals, double *dmin, double *dmax) {
  int64_t n = s->n, lnz = 0, unz = 0;
  double *x = s->x;
  *dmin = INFINITY; *dmax = 0.0;
  for (int64_t i = 0; i < n; ++i) { s->pinv[i] = -1; s->mark[i] = 0; }
  for (int64_t k = 0; k < n; ++k) {
    s->Lp[k] = lnz; s->Up[k] = unz;
    if (!grow(&s->Li, &s->Lx, &s->lcap, lnz + n) || !grow(&s->Ui, &s->Ux, &s->ucap, unz + n))
      return LU_SINGULAR;
    int64_t col = s->q[k];
    int64_t top = reach(s, col, k + 1);
    for (int64_t p = s->Ap[col]; p < s->Ap[col + 1]; ++p) x[s->Ai[p]] += vals[p];
    /* the triangular solve with the columns of L, in topological order */
    for (int64_t p = top; p < n; ++p) {
      int64_t i = s->xi[p], J = s->pinv[i];
      if (J < 0) continue;
      double xi = x[i];
      if (xi == 0.0) continue;
      for (int64_t q = s->Lp[J] + 1; q < s->Lp[J + 1]; ++q) x[s->Li[q]] -= s->Lx[q] * xi;
    }
    int64_t ipiv = -1; double big = -1.0;
    for (int64_t p = top; p < n; ++p) {
      int64_t i = s->xi[p];
      if (s->pinv[i] < 0) {
        double a = fabs(x[i]);
        if (a > big) { big = a; ipiv = i; }
      } else {
        s->Ui[unz] = s->pinv[i]; s->Ux[unz++] = x[i];
      }
    }
    int64_t pr = s->pref[k];
    if (pr >= 0 && s->pinv[pr] < 0 && s->mark[pr] == k + 1 &&
        fabs(x[pr]) >= PIVOT_TOL * big)
      ipiv = pr;
    if (ipiv < 0 || !(big > 0.0) || !isfinite(big)) {
      for (int64_t p = top; p < n; ++p) x[s->xi[p]] = 0.0;
      return LU_SINGULAR;
    }
    double piv = x[ipiv], a = fabs(piv);
    if (a < *dmin) *dmin = a;
    if (a > *dmax) *dmax = a;
    s->Ud[k] = piv;
    s->pinv[ipiv] = k; s->prow[k] = ipiv;
    s->Li[lnz] = ipiv; s->Lx[lnz++] = 1.0;
    for (int64_t p = top; p < n; ++p) {
      int64_t i = s->xi[p];
      if (s->pinv[i] < 0) { s->Li[lnz] = i; s->Lx[lnz++] = x[i] / piv; }
      x[i] = 0.0;
    }
  }
  s->Lp[n] = lnz; s->Up[n] = unz;
  return LU_OK;
}

/* factor the values in Ax: LU_OK, LU_SINGULAR or LU_NONFINITE */
int sparse_factor(void *h) {
  sparse_lu *s = (sparse_lu *)h;
  int64_t n = s->n;
  double dmin, dmax;
  s->equil = 0; s->ok = 0;
  for (int64_t p = 0; p < s->nnz; ++p) if (!isfinite(s->Ax[p])) return LU_NONFINITE;
  if (lu_numeric(s, s->Ax, &dmin, &dmax) == LU_OK && pivots_ok(dmin, dmax)) {
    s->ok = 1;
    return LU_OK;
  }
  /* a small pivot may only reflect the units: judge the equilibrated matrix */
  for (int64_t i = 0; i < n; ++i) s->r[i] = 0.0;
  for (int64_t j = 0; j < n; ++j)
    for (int64_t p = s->Ap[j]; p < s->Ap[j + 1]; ++p)
      if (fabs(s->Ax[p]) > s->r[s->Ai[p]]) s->r[s->Ai[p]] = fabs(s->Ax[p]);
  for (int64_t i = 0; i < n; ++i) s->r[i] = 1.0 / (s->r[i] > 1e-300 ? s->r[i] : 1e-300);
  for (int64_t j = 0; j < n; ++j) {
    double a = 0.0;
    for (int64_t p = s->Ap[j]; p < s->Ap[j + 1]; ++p) {
      double b = fabs(s->Ax[p]) * s->r[s->Ai[p]];
      if (b > a) a = b;
    }
    s->c[j] = 1.0 / (a > 1e-300 ? a : 1e-300);
    for (int64_t p = s->Ap[j]; p < s->Ap[j + 1]; ++p)
      s->Bx[p] = s->Ax[p] * s->r[s->Ai[p]] * s->c[j];
  }
  if (lu_numeric(s, s->Bx, &dmin, &dmax) != LU_OK || !pivots_ok(dmin, dmax))
    return LU_SINGULAR;
  s->equil = 1; s->ok = 1;
  return LU_OK;
}

/* b := A^{-1} b with the last factorization (P A Q = L U, rows of L by original row) */
void sparse_solve(void *h, double *b) {
  sparse_lu *s = (sparse_lu *)h;
  int64_t n = s->n;
  double *w = s->w;
  if (s->equil) for (int64_t i = 0; i < n; ++i) b[i] *= s->r[i];
  for (int64_t k = 0; k < n; ++k) {          /* L y = P b, y_k stored at its pivot row */
    double v = b[s->prow[k]];
    w[k] = v;
    if (v != 0.0)
      for (int64_t p = s->Lp[k] + 1; p < s->Lp[k + 1]; ++p) b[s->Li[p]] -= s->Lx[p] * v;
  }
  for (int64_t k = n - 1; k >= 0; --k) {     /* U z = y */
    double v = w[k] / s->Ud[k];
    w[k] = v;
    if (v != 0.0)
      for (int64_t p = s->Up[k]; p < s->Up[k + 1]; ++p) w[s->Ui[p]] -= s->Ux[p] * v;
  }
  for (int64_t k = 0; k < n; ++k) b[s->q[k]] = w[k];
  if (s->equil) for (int64_t j = 0; j < n; ++j) b[j] *= s->c[j];
}

/* nnz of L (with its unit diagonal) and U (with its diagonal) of the last factorization */
int64_t sparse_nnz(void *h) {
  sparse_lu *s = (sparse_lu *)h;
  return s->Lp[s->n] + s->Up[s->n] + s->n;
}
