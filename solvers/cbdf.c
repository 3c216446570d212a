/* The BDF step loop of acausal.solvers.bdf in C (see cbdf.py for why and when).

   The same method as the Python loop, line for line: IDA's fixed-leading-coefficient
   BDF (Brenan, Campbell & Petzold 1996, ch. 5; Hindmarsh et al. 2005), modified divided
   differences phi, the corrector of acausal.solvers.corrector (simplified Newton, the
   2/(1+cj/cj_old) scaling, one unscaled correction for algebraic rows, the Newton test
   with and without the self-scaled components), the error test and order/step control
   of bdf.py.  Dense LU with partial pivoting (above cbdf.py's MAX_DENSE unknowns the
   sparse LU of cbdf_sparse.c, I_SPARSE); a matrix whose pivots look singular is
   judged again equilibrated (rows, then columns, to a largest entry of one), as
   acausal.solvers.linalg does with LAPACK.

   All state lives in three arrays owned by Python: dv (doubles), iv (longs) and pv
   (pointers); the indices below are repeated in cbdf.py.  cbdf_run takes steps until
   something needs Python: a zero-crossing function changed sign, a step landed on the
   stop time, the output buffer is full, the step budget is used up, a step failed, or
   the current choice of states (dynamic state selection, cbdf_dyn.c) must be looked at
   again. */
#include <math.h>
#include <string.h>
#include <float.h>
/* dense_factor, dense_solve (cbdf_lu.c), dyn_due (cbdf_dyn.c) and sparse_jacobian,
   sparse_factor, sparse_solve (cbdf_sparse.c) are defined before this file: cbdf.py
   builds the four files as one translation unit, in that order. */

/* dv */
enum { D_TN, D_TPREV, D_TSTOP, D_HH, D_HUSED, D_CJ, D_CJOLD, D_CJLAST, D_CJRATIO, D_SS,
       D_RTOL, D_MAXSTEP, D_FAIL_T, D_FAIL_H, D_FAIL_CJ, D_FAIL_TJ, D_PSI = 16,
       D_ALPHA = 24, D_BETA = 32, D_SIGMA = 40, D_GAMMA = 48, D_ALPHAS = 56, D_SIZE = 64 };
/* iv */
enum { I_N, I_KK, I_KUSED, I_PHASE, I_NS, I_NST, I_FORCE, I_KMAX, I_MAXORD, I_NROOTS,
       I_MODE, I_BUDGET, I_CAP, I_COUNT, I_NEVAL, I_IEVAL, I_ALLSTEPS, I_FAILKIND,
       I_HASFAIL, I_HASLAST, I_PENDING, I_ANYALG, I_ANYSS, I_EQUIL,
       I_NRE, I_NJE, I_NLU, I_NNI, I_NETF, I_NCF, I_NSTEPS, I_SPARSE, I_ORD = 32,
       I_NRES = 40, I_NSZ, I_NLINK, I_NJAC, I_NREL, I_NDISC, I_NROWS, I_SIZE = 48 };
/* pv */
enum { P_PHI, P_ATOL, P_SSMASK, P_ERRMASK, P_ALG, P_SCRATCH, P_LU, P_PIV, P_TEVAL,
       P_OUT_T, P_OUT_Y, P_OUT_YP, P_WEIGHTED, P_LASTERR, P_GPREV, P_SIGNREF, P_G,
       P_YP, P_FAILY, P_FAILYP, P_SPLU,
       P_RESFN = 24, P_JACFN, P_ROOTSFN, P_SCALESFN, P_PAR, P_M, P_MW, P_MOUT, P_JROWS,
       P_JCOLS, P_JSIGN, P_STATEZ, P_LINKS, P_LINKD, P_JVALS, P_RSIGN, P_RSIDE, P_RNOM,
       P_TIMED, P_OFFSET, P_RV, P_RSCALE, P_DYNL, P_DYND, P_SIZE = 48 };

enum { R_BUDGET = 0, R_FULL = 1, R_SPECIAL = 2, R_FAIL = 3 };
enum { F_NONE, F_ERRTEST, F_NEWTON, F_STEPSIZE, F_SINGULAR, F_NONFINITE };

#define MAXORD 5
#define EPCON 0.33
#define MAXCOR 4
#define RATEMAX 0.9
#define XRATE 0.25
#define SS_FLOOR 0.1
#define TINY 1e-8
#define MAXNEF 10
#define MAXNCF 10
#define MAXSING 3
#define ZERO_RTOL 1e-10
#define ZERO_NOMINAL 1e-12

typedef int (*genfn)(double, const double *, const double *, const double *, double *,
                     double *);
typedef int (*cb_res)(double, const double *, const double *, double *);
typedef int (*cb_jac)(double, const double *, const double *, double, double *);
typedef int (*cb_roots)(double, const double *, const double *, double *);

typedef struct {
  double *dv; long *iv; void **pv;
  long n;
  double *phi, *ewt_n, *ewt, *ewt_err, *ee, *delta, *ypred, *yppred, *ytmp, *yptmp,
         *fallback, *rhs, *lu, *req, *ceq;
  long *piv;
} ctx_t;

/* ------------------------------------------------------------------ the problem */
static int residual(ctx_t *c, double t, const double *y, const double *yp, double *F) {
  void **pv = c->pv; long *iv = c->iv;
  c->iv[I_NRE]++;
  if (iv[I_MODE] == 1) return ((cb_res)pv[P_RESFN])(t, y, yp, F);
  long nres = iv[I_NRES], nsz = iv[I_NSZ], nl = iv[I_NLINK];
  double *out = (double *)pv[P_MOUT];
  ((genfn)pv[P_RESFN])(t, y, (double *)pv[P_PAR], (double *)pv[P_M], out,
                       (double *)pv[P_MW]);
  const long *sz = (long *)pv[P_STATEZ], *ls = (long *)pv[P_LINKS],
             *ld = (long *)pv[P_LINKD];
  for (long i = 0; i < nres; ++i) F[i] = out[i];
  for (long i = 0; i < nsz; ++i) F[nres + i] = yp[sz[i]] - out[nres + i];
  long r0 = nres + nsz;
  for (long i = 0; i < nl; ++i) F[r0 + i] = yp[ls[i]] - y[ld[i]];
  return 0;
}

/* dense row-major dF/dy + cj dF/dy' */
static void jacobian(ctx_t *c, double t, const double *y, const double *yp, double cj,
                     double *J) {
  void **pv = c->pv; long *iv = c->iv; long n = c->n;
  c->iv[I_NJE]++;
  if (iv[I_MODE] == 1) { ((cb_jac)pv[P_JACFN])(t, y, yp, cj, J); return; }
  double *v = (double *)pv[P_JVALS];
  ((genfn)pv[P_JACFN])(t, y, (double *)pv[P_PAR], (double *)pv[P_M], v,
                       (double *)pv[P_MW]);
  const long *jr = (long *)pv[P_JROWS], *jc = (long *)pv[P_JCOLS];
  const double *js = (double *)pv[P_JSIGN];
  if (iv[I_SPARSE]) {     /* into the sparse LU's values, J unused */
    sparse_jacobian(pv[P_SPLU], v, js, iv[I_NJAC], iv[I_NSZ], iv[I_NLINK], cj);
    return;
  }
  memset(J, 0, sizeof(double) * n * n);
  for (long e = 0; e < iv[I_NJAC]; ++e) J[jr[e] * n + jc[e]] += js[e] * v[e];
  long nres = iv[I_NRES], nsz = iv[I_NSZ], nl = iv[I_NLINK];
  const long *sz = (long *)pv[P_STATEZ], *ls = (long *)pv[P_LINKS],
             *ld = (long *)pv[P_LINKD];
  for (long i = 0; i < nsz; ++i) J[(nres + i) * n + sz[i]] += cj;
  long r0 = nres + nsz;
  for (long i = 0; i < nl; ++i) {
    J[(r0 + i) * n + ls[i]] += cj;
    J[(r0 + i) * n + ld[i]] -= 1.0;
  }
}

/* the oriented zero-crossing functions of acausal.runtime.modes (plus their offsets) */
static void roots(ctx_t *c, double t, const double *y, const double *yp, double *r) {
  void **pv = c->pv; long *iv = c->iv;
  if (iv[I_MODE] == 1) { ((cb_roots)pv[P_ROOTSFN])(t, y, yp, r); return; }
  long nrel = iv[I_NREL], ndisc = iv[I_NDISC];
  double *v = (double *)pv[P_RV], *sc = (double *)pv[P_RSCALE];
  const double *p = (double *)pv[P_PAR], *m = (double *)pv[P_M];
  double *w = (double *)pv[P_MW];
  ((genfn)pv[P_ROOTSFN])(t, y, p, m, v, w);
  const double *sg = (double *)pv[P_RSIGN], *sd = (double *)pv[P_RSIDE],
               *nom = (double *)pv[P_RNOM], *timed = (double *)pv[P_TIMED],
               *off = (double *)pv[P_OFFSET];
  if (nrel) {
    ((genfn)pv[P_SCALESFN])(t, y, p, m, sc, w);
    for (long k = 0; k < nrel; ++k)
      r[k] = sg[k] * v[k] + sd[k] * (ZERO_RTOL * fabs(sc[k]) + ZERO_NOMINAL * nom[k]);
  }
  for (long j = 0; j < ndisc; ++j) {
    double u = v[nrel + j], nn = m[nrel + j], tol = ZERO_RTOL * (fabs(u) + 1.0);
    r[nrel + 2 * j] = u - nn + tol;
    r[nrel + 2 * j + 1] = nn + 1.0 - u + (timed[nrel + j] != 0.0 ? tol : -tol);
  }
  for (long k = 0; k < iv[I_NROOTS]; ++k) r[k] += off[k];
}

/* ------------------------------------------------------------------ linear algebra */
static int factor(ctx_t *c, double *J) {
  if (c->iv[I_SPARSE]) return sparse_factor(c->pv[P_SPLU]);
  int equil = 0;
  int k = dense_factor(J, c->lu, c->piv, c->req, c->ceq, c->n, &equil);
  c->iv[I_EQUIL] = equil;
  return k;
}

static void solve(ctx_t *c, double *b) {
  if (c->iv[I_SPARSE]) { sparse_solve(c->pv[P_SPLU], b); return; }
  dense_solve(c->lu, c->piv, c->iv[I_EQUIL] ? c->req : 0, c->ceq, c->n, b);
}

static double wrms(const double *v, const double *w, long n) {
  double s = 0.0;
  for (long i = 0; i < n; ++i) { double x = v[i] * w[i]; s += x * x; }
  return sqrt(s / n);
}

/* ------------------------------------------------------------------ corrector */
/* setup: 0 or a failure kind */
static int setup(ctx_t *c, double t, const double *y, const double *yp) {
  double *dv = c->dv; long *iv = c->iv;
  double *J = (double *)c->pv[P_SCRATCH];   /* the first n*n of scratch */
  jacobian(c, t, y, yp, dv[D_CJ], J);
  iv[I_NLU]++;
  int k = factor(c, J);
  if (k) {
    dv[D_FAIL_TJ] = t; dv[D_FAIL_CJ] = dv[D_CJ];
    memcpy(c->pv[P_FAILY], y, sizeof(double) * c->n);
    memcpy(c->pv[P_FAILYP], yp, sizeof(double) * c->n);
    return k;
  }
  dv[D_CJOLD] = dv[D_CJ]; dv[D_CJRATIO] = 1.0; dv[D_SS] = 20.0; iv[I_FORCE] = 0;
  return 0;
}

/* one simplified-Newton iteration: 1 converged (ee), 0 failed; *fb: a fallback iterate
   (the test without the self-scaled components passed) is in c->fallback */
static int iterate(ctx_t *c, double tnew, double cj, int *fb, int *have_last) {
  double *dv = c->dv; long *iv = c->iv; long n = c->n;
  double *ee = c->ee, *delta = c->delta, *w = c->ewt_n;
  int rest = iv[I_ANYSS] != 0;
  double scale = dv[D_CJRATIO] != 1.0 ? 2.0 / (1.0 + dv[D_CJRATIO]) : 1.0;
  double first = 0.0, first_rest = 0.0, ss0 = dv[D_SS];
  *fb = 0; *have_last = 0;
  for (int m = 0; m < MAXCOR; ++m) {
    if (m == 0) residual(c, tnew, c->ypred, c->yppred, delta);
    else {
      for (long i = 0; i < n; ++i) {
        c->ytmp[i] = c->ypred[i] + ee[i];
        c->yptmp[i] = c->yppred[i] + cj * ee[i];
      }
      residual(c, tnew, c->ytmp, c->yptmp, delta);
    }
    iv[I_NNI]++;
    solve(c, delta);
    for (long i = 0; i < n; ++i) delta[i] *= -scale;
    if (m == 0) memcpy(ee, delta, sizeof(double) * n);
    else for (long i = 0; i < n; ++i) ee[i] += delta[i];
    double delnrm = wrms(delta, w, n);
    if (!isfinite(delnrm)) { *fb = 0; return 0; }
    if (m == 0) {
      first = delnrm;
      double ssm = dv[D_SS] > SS_FLOOR ? dv[D_SS] : SS_FLOOR;
      if (delnrm <= TINY * EPCON || ssm * delnrm <= EPCON) return 1;
    } else {
      double rate = first > 0 ? pow(delnrm / first, 1.0 / m) : 0.0;
      if (rate > RATEMAX) goto fail;
      dv[D_SS] = rate / (1.0 - rate);
      if (dv[D_SS] * delnrm <= EPCON) return 1;
    }
    if (rest && !*fb) {
      double r = wrms(delta, c->ewt, n); int ok;
      if (m == 0) {
        first_rest = r;
        double ssm = ss0 > SS_FLOOR ? ss0 : SS_FLOOR;
        ok = r <= TINY * EPCON || ssm * r <= EPCON;
      } else {
        double rate = first_rest > 0 ? pow(r / first_rest, 1.0 / m) : 0.0;
        ok = rate <= RATEMAX && rate / (1.0 - rate) * r <= EPCON;
      }
      if (ok) { memcpy(c->fallback, ee, sizeof(double) * n); *fb = 1; }
    }
  }
fail:
  for (long i = 0; i < n; ++i) ((double *)c->pv[P_WEIGHTED])[i] = delta[i] * w[i];
  *have_last = 1;
  return 0;
}

/* the correction ee of the step to tnew: 0, -1 (Newton failure) or a setup failure kind */
static int corrector(ctx_t *c, double tnew) {
  double *dv = c->dv; long *iv = c->iv; long n = c->n;
  double cj = dv[D_CJ];
  dv[D_CJRATIO] = cj / dv[D_CJOLD];
  double lo = (1.0 - XRATE) / (1.0 + XRATE);
  int call_setup = iv[I_FORCE] || !(lo <= dv[D_CJRATIO] && dv[D_CJRATIO] <= 1.0 / lo);
  if (cj != dv[D_CJLAST]) dv[D_SS] = 100.0;
  int fresh = 0;
  for (;;) {
    if (call_setup) {
      int k = setup(c, tnew, c->ypred, c->yppred);
      if (k) return k;
      fresh = 1;
    }
    int fb, have_last;
    if (iterate(c, tnew, cj, &fb, &have_last)) {
      if (dv[D_CJRATIO] != 1.0 && iv[I_ANYALG]) {
        /* one unscaled correction: the algebraic rows do not contain cj */
        for (long i = 0; i < n; ++i) {
          c->ytmp[i] = c->ypred[i] + c->ee[i];
          c->yptmp[i] = c->yppred[i] + cj * c->ee[i];
        }
        iv[I_NNI]++;
        residual(c, tnew, c->ytmp, c->yptmp, c->delta);
        solve(c, c->delta);
        int fin = 1;
        for (long i = 0; i < n; ++i) if (!isfinite(c->delta[i])) { fin = 0; break; }
        if (fin) for (long i = 0; i < n; ++i) c->ee[i] -= c->delta[i];
      }
      return 0;
    }
    if (fresh) {
      if (fb) { memcpy(c->ee, c->fallback, sizeof(double) * n); return 0; }
      iv[I_HASFAIL] = have_last;
      return -1;
    }
    call_setup = 1;
  }
}

/* ------------------------------------------------------------------ step */

static double set_coeffs(ctx_t *c) {
  double *dv = c->dv; long *iv = c->iv; long n = c->n;
  long kk = iv[I_KK]; double hh = dv[D_HH];
  double *psi = dv + D_PSI, *alpha = dv + D_ALPHA, *beta = dv + D_BETA,
         *sigma = dv + D_SIGMA, *gamma = dv + D_GAMMA;
  if (hh != dv[D_HUSED] || kk != iv[I_KUSED]) iv[I_NS] = 0;
  iv[I_NS] = iv[I_NS] + 1 < iv[I_KUSED] + 2 ? iv[I_NS] + 1 : iv[I_KUSED] + 2;
  if (kk + 1 >= iv[I_NS]) {
    beta[0] = alpha[0] = sigma[0] = 1.0; gamma[0] = 0.0;
    double temp1 = hh;
    for (long i = 1; i <= kk; ++i) {
      double temp2 = psi[i - 1];
      psi[i - 1] = temp1;
      beta[i] = beta[i - 1] * psi[i - 1] / temp2;
      temp1 = temp2 + hh;
      alpha[i] = hh / temp1;
      sigma[i] = i * sigma[i - 1] * alpha[i];
      gamma[i] = gamma[i - 1] + alpha[i - 1] / hh;
    }
    psi[kk] = temp1;
  }
  double alphas = dv[D_ALPHAS + kk], alpha0 = 0.0;
  for (long i = 0; i < kk; ++i) alpha0 -= alpha[i];
  dv[D_CJLAST] = dv[D_CJ];
  dv[D_CJ] = -alphas / hh;
  double a = fabs(alpha[kk] + alphas - alpha0), ck = a > alpha[kk] ? a : alpha[kk];
  for (long i = iv[I_NS]; i <= kk; ++i) {
    double *p = c->phi + i * n;
    for (long j = 0; j < n; ++j) p[j] *= beta[i];
  }
  return ck;
}

static void restore(ctx_t *c, double saved_t) {
  double *dv = c->dv; long *iv = c->iv; long n = c->n, kk = iv[I_KK];
  dv[D_TN] = saved_t;
  for (long j = 1; j <= kk; ++j) dv[D_PSI + j - 1] = dv[D_PSI + j] - dv[D_HH];
  for (long i = iv[I_NS]; i <= kk; ++i) {
    double *p = c->phi + i * n;
    for (long j = 0; j < n; ++j) p[j] /= dv[D_BETA + i];
  }
}

static void shrink(ctx_t *c, double rr) {
  double *dv = c->dv; long n = c->n;
  dv[D_HH] *= rr;
  if (c->iv[I_NST] == 0) {
    dv[D_PSI] = dv[D_HH];
    for (long j = 0; j < n; ++j) c->phi[n + j] *= rr;
  }
}

static void update_weights(ctx_t *c) {
  long n = c->n; double rtol = c->dv[D_RTOL];
  const double *atol = (double *)c->pv[P_ATOL], *ssm = (double *)c->pv[P_SSMASK],
               *em = (double *)c->pv[P_ERRMASK];
  for (long i = 0; i < n; ++i) {
    c->ewt_n[i] = 1.0 / (rtol * fabs(c->phi[i]) + atol[i]);
    c->ewt[i] = c->ewt_n[i] * ssm[i];
    c->ewt_err[i] = c->ewt[i] * em[i];
  }
}

static void next_step(ctx_t *c, double err_knew) {
  double *dv = c->dv;
  double rr = pow(2.0 * err_knew + 1e-4, -1.0 / (c->iv[I_KK] + 1));
  if (rr >= 2.0) dv[D_HH] = fmin(2.0 * dv[D_HH], dv[D_MAXSTEP]);
  else if (rr <= 1.0) dv[D_HH] *= fmax(0.5, fmin(0.9, rr));
}

static void complete_step(ctx_t *c, double err_k, double err_km1, long knew) {
  double *dv = c->dv; long *iv = c->iv; long n = c->n;
  double *ee = c->ee, *phi = c->phi;
  long kk = iv[I_KK];
  iv[I_NST]++; iv[I_NSTEPS]++; iv[I_ORD + kk]++;
  long kdiff = kk - iv[I_KUSED];
  iv[I_KUSED] = kk; dv[D_HUSED] = dv[D_HH];
  if (knew == kk - 1 || kk >= iv[I_KMAX]) iv[I_PHASE] = 1;
  if (iv[I_PHASE] == 0) {
    if (iv[I_NST] > 1) {
      iv[I_KK] = kk + 1;
      dv[D_HH] = fmin(2.0 * dv[D_HH], dv[D_MAXSTEP]);
    }
  } else {
    int action = 0;   /* 0 maintain, 1 raise, -1 lower */
    double err_kp1 = 0.0;
    if (knew == kk - 1) action = -1;
    else if (kk >= iv[I_KMAX] || kk + 1 >= iv[I_NS] || kdiff == 1) action = 0;
    else {
      double *p1 = phi + (kk + 1) * n, s = 0.0;
      for (long i = 0; i < n; ++i) {
        double x = (ee[i] - p1[i]) * c->ewt_err[i];
        s += x * x;
      }
      err_kp1 = sqrt(s / n) / (kk + 2);
      double terr_k = (kk + 1) * err_k, terr_kp1 = (kk + 2) * err_kp1;
      if (kk == 1) action = terr_kp1 >= 0.5 * terr_k ? 0 : 1;
      else if (kk * err_km1 <= fmin(terr_k, terr_kp1)) action = -1;
      else if (terr_kp1 >= terr_k) action = 0;
      else action = 1;
    }
    double err_knew = err_k;
    if (action == 1) { iv[I_KK] = kk + 1; err_knew = err_kp1; }
    else if (action == -1) { iv[I_KK] = kk - 1; err_knew = err_km1; }
    next_step(c, err_knew);
  }
  long ku = iv[I_KUSED];
  if (ku < iv[I_MAXORD]) memcpy(phi + (ku + 1) * n, ee, sizeof(double) * n);
  for (long j = 0; j < n; ++j) phi[ku * n + j] += ee[j];
  for (long k = ku - 1; k >= 0; --k)
    for (long j = 0; j < n; ++j) phi[k * n + j] += phi[(k + 1) * n + j];
  dv[D_TPREV] = dv[D_TN] - dv[D_HUSED];
  double *le = (double *)c->pv[P_LASTERR], *yp = (double *)c->pv[P_YP];
  for (long i = 0; i < n; ++i) {
    le[i] = ee[i] * c->ewt_err[i];
    yp[i] = c->yppred[i] + dv[D_CJ] * ee[i];
  }
  iv[I_HASLAST] = 1;
}

/* one accepted step: 0, or a failure kind (F_...) */
static int step(ctx_t *c) {
  double *dv = c->dv; long *iv = c->iv; long n = c->n;
  int ncf = 0, nef = 0, nsing = 0;
  double saved_t = dv[D_TN];
  iv[I_HASFAIL] = 0;
  update_weights(c);
  double ck, err_k, err_km1; long knew;
  for (;;) {
    dv[D_HH] = fmin(dv[D_HH], dv[D_MAXSTEP]);
    double tstop = dv[D_TSTOP], remaining = tstop - saved_t;
    double hmin = 16.0 * DBL_EPSILON *
                  fmax(fmax(fabs(dv[D_TN]), fabs(dv[D_HUSED])), 1e-300);
    int landing = isfinite(tstop) && dv[D_HH] >= remaining - 64 * DBL_EPSILON * fabs(tstop);
    if (landing) {
      if (remaining <= hmin) { dv[D_TPREV] = saved_t; dv[D_TN] = tstop; return -1; }
      dv[D_HH] = remaining;
    }
    if (dv[D_HH] < hmin) {
      dv[D_FAIL_T] = saved_t; dv[D_FAIL_H] = dv[D_HH];
      return F_STEPSIZE;
    }
    ck = set_coeffs(c);
    double tnew = landing ? tstop : saved_t + dv[D_HH];
    dv[D_TN] = tnew;
    long kk = iv[I_KK];
    const double *gamma = dv + D_GAMMA;
    for (long j = 0; j < n; ++j) {
      double s = c->phi[j], sp = 0.0;
      for (long i = 1; i <= kk; ++i) {
        s += c->phi[i * n + j];
        sp += gamma[i] * c->phi[i * n + j];
      }
      c->ypred[j] = s; c->yppred[j] = sp;
    }
    int k = corrector(c, tnew);
    if (k == F_SINGULAR || k == F_NONFINITE) {
      restore(c, saved_t);
      if (++nsing >= MAXSING) { dv[D_FAIL_T] = saved_t; dv[D_FAIL_H] = dv[D_HH]; return k; }
      shrink(c, 0.25); iv[I_FORCE] = 1; continue;
    }
    if (k == -1) {
      restore(c, saved_t);
      iv[I_NCF]++; ncf++; iv[I_PHASE] = 1;
      if (ncf >= MAXNCF) {
        dv[D_FAIL_T] = saved_t; dv[D_FAIL_H] = dv[D_HH];
        return F_NEWTON;
      }
      shrink(c, 0.25); iv[I_FORCE] = 1; continue;
    }
    /* the error test (IDATestError) */
    const double *w = c->ewt_err, *sigma = dv + D_SIGMA;
    double enorm_k = wrms(c->ee, w, n);
    err_k = sigma[kk] * enorm_k;
    double terr_k = (kk + 1) * err_k;
    err_km1 = 0.0; knew = kk;
    if (kk > 1) {
      double *d = c->delta, s = 0.0;
      for (long j = 0; j < n; ++j) {
        d[j] = c->phi[kk * n + j] + c->ee[j];
        double x = d[j] * w[j];
        s += x * x;
      }
      err_km1 = sigma[kk - 1] * sqrt(s / n);
      double terr_km1 = kk * err_km1;
      if (kk > 2) {
        s = 0.0;
        for (long j = 0; j < n; ++j) {
          d[j] += c->phi[(kk - 1) * n + j];
          double x = d[j] * w[j];
          s += x * x;
        }
        double terr_km2 = (kk - 1) * sigma[kk - 2] * sqrt(s / n);
        if (fmax(terr_km1, terr_km2) <= terr_k) knew = kk - 1;
      } else if (terr_km1 <= 0.5 * terr_k) knew = kk - 1;
    }
    if (ck * enorm_k <= 1.0) break;
    restore(c, saved_t);
    iv[I_NETF]++; nef++;
    double *wt = (double *)c->pv[P_WEIGHTED];
    for (long j = 0; j < n; ++j) wt[j] = c->ee[j] * w[j];
    iv[I_HASFAIL] = 1; iv[I_PHASE] = 1;
    if (nef >= MAXNEF) {
      dv[D_FAIL_T] = saved_t; dv[D_FAIL_H] = dv[D_HH];
      return F_ERRTEST;
    }
    iv[I_KMAX] = iv[I_MAXORD];
    if (iv[I_NST] == 0 && nef <= 3) {
      double rr = 0.9 * pow(2.0 * err_k + 1e-4, -0.5);
      shrink(c, fmax(1e-3, fmin(0.9, rr)));
    } else if (nef == 1) {
      iv[I_KK] = knew;
      double err_knew = knew == kk ? err_k : err_km1;
      double rr = 0.9 * pow(2.0 * err_knew + 1e-4, -1.0 / (iv[I_KK] + 1));
      shrink(c, fmax(0.25, fmin(0.9, rr)));
    } else {
      double rr = 0.25;
      if (kk == 1) rr = fmax(1e-3, fmin(0.25, 0.9 * pow(2.0 * err_k + 1e-4, -0.5)));
      iv[I_KK] = nef == 2 ? knew : 1;
      shrink(c, rr);
    }
  }
  complete_step(c, err_k, err_km1, knew);
  return 0;
}

/* ------------------------------------------------------------------ output */
void cbdf_interpolate(double *dv, long *iv, double *phi, double t, double *y, double *yp) {
  long n = iv[I_N], kord = iv[I_KUSED] > 1 ? iv[I_KUSED] : 1;
  double delt = t - dv[D_TN], *psi = dv + D_PSI;
  double cc = 1.0, d = 0.0, gam = delt / psi[0];
  memcpy(y, phi, sizeof(double) * n);
  memset(yp, 0, sizeof(double) * n);
  for (long j = 1; j <= kord; ++j) {
    d = d * gam + cc / psi[j - 1];
    cc = cc * gam;
    gam = (delt + psi[j - 1]) / psi[j];
    const double *p = phi + j * n;
    for (long i = 0; i < n; ++i) { y[i] += cc * p[i]; yp[i] += d * p[i]; }
  }
}

static int emit(ctx_t *c, double t, const double *y, const double *yp) {
  long *iv = c->iv; long n = c->n;
  if (iv[I_COUNT] >= iv[I_CAP]) return 0;
  long k = iv[I_COUNT]++;
  ((double *)c->pv[P_OUT_T])[k] = t;
  double *oy = (double *)c->pv[P_OUT_Y] + k * n, *oyp = (double *)c->pv[P_OUT_YP] + k * n;
  if (y) { memcpy(oy, y, sizeof(double) * n); memcpy(oyp, yp, sizeof(double) * n); }
  else cbdf_interpolate(c->dv, iv, c->phi, t, oy, oyp);
  return 1;
}

/* the output of the accepted interval (t_prev, t]; 0 when the buffer filled first */
static int emit_step(ctx_t *c) {
  long *iv = c->iv; double *dv = c->dv;
  if (iv[I_ALLSTEPS]) return emit(c, dv[D_TN], c->phi, (double *)c->pv[P_YP]);
  const double *ev = (double *)c->pv[P_TEVAL];
  while (iv[I_IEVAL] < iv[I_NEVAL] && ev[iv[I_IEVAL]] <= dv[D_TN]) {
    double te = ev[iv[I_IEVAL]];
    if (te >= dv[D_TPREV] && !emit(c, te, 0, 0)) return 0;
    iv[I_IEVAL]++;
  }
  return 1;
}

/* ------------------------------------------------------------------ the loop */
int cbdf_run(double *dv, long *iv, void **pv) {
  ctx_t c;
  long n = iv[I_N];
  c.dv = dv; c.iv = iv; c.pv = pv; c.n = n;
  c.phi = (double *)pv[P_PHI];
  /* after the dense matrix (none with the sparse LU) */
  double *s = (double *)pv[P_SCRATCH] + (iv[I_SPARSE] ? 0 : n * n);
  c.ewt_n = s; c.ewt = s + n; c.ewt_err = s + 2 * n; c.ee = s + 3 * n; c.delta = s + 4 * n;
  c.ypred = s + 5 * n; c.yppred = s + 6 * n; c.ytmp = s + 7 * n; c.yptmp = s + 8 * n;
  c.fallback = s + 9 * n; c.rhs = s + 10 * n; c.req = s + 11 * n; c.ceq = s + 12 * n;
  c.lu = (double *)pv[P_LU]; c.piv = (long *)pv[P_PIV];
  long nr = iv[I_NROOTS];
  double *g = (double *)pv[P_G], *gprev = (double *)pv[P_GPREV],
         *ref = (double *)pv[P_SIGNREF], *off = (double *)pv[P_OFFSET];
  iv[I_PENDING] = 0;
  for (;;) {
    if (iv[I_BUDGET] <= 0) return R_BUDGET;
    if (iv[I_ALLSTEPS] && iv[I_COUNT] >= iv[I_CAP]) return R_FULL;
    int k = step(&c);
    if (k == -1) return R_SPECIAL;       /* landed on the stop time without a step */
    if (k) { iv[I_FAILKIND] = k; return R_FAIL; }
    iv[I_BUDGET]--;
    if (dv[D_TN] == dv[D_TSTOP]) return R_SPECIAL;
    if (nr) {
      roots(&c, dv[D_TN], c.phi, (double *)pv[P_YP], g);
      int crossed = 0, finite = 1;
      for (long i = 0; i < nr; ++i) {
        if (!isfinite(g[i])) finite = 0;
        if (ref[i] != 0.0 && g[i] * ref[i] <= 0.0) crossed = 1;
      }
      if (crossed || !finite) return R_SPECIAL;   /* Python locates and handles it */
      for (long i = 0; i < nr; ++i) {
        if (ref[i] == 0.0) ref[i] = g[i] > 0 ? 1.0 : (g[i] < 0 ? -1.0 : 0.0);
        gprev[i] = g[i];
      }
      /* offsets of items armed at zero end once they have left it on their own side */
      if (iv[I_MODE] == 0)
        for (long i = 0; i < nr; ++i)
          if (off[i] != 0.0 && g[i] - off[i] >= 0.0) off[i] = 0.0;
    }
    int due = pv[P_DYNL] && dyn_due((long *)pv[P_DYNL], (double *)pv[P_DYND],
                                    iv[I_MODE] == 0 ? pv[P_JACFN] : 0, dv[D_TN], c.phi,
                                    (double *)pv[P_PAR], (double *)pv[P_M],
                                    (double *)pv[P_JVALS], (double *)pv[P_MW], iv[I_NJAC]);
    if (!emit_step(&c)) { iv[I_PENDING] = 1; return R_FULL; }
    if (due) return R_FULL;            /* Python re-chooses the states, then goes on */
  }
}
