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

   All state lives in one struct, cbdf_state (cbdf.h, a comment on every field), whose
   buffers Python owns.  cbdf_run takes steps until something needs Python: a
   zero-crossing function changed sign, a step landed on the stop time, the output
   buffer is full, the step budget is used up, a step failed, or the current choice of
   states (dynamic state selection, cbdf_dyn.c) must be looked at again.  The four
   files are one translation unit (cbdf_loop.c includes them). */
#include <math.h>
#include <string.h>
#include <float.h>
#include "cbdf.h"

enum { R_BUDGET = 0, R_FULL = 1, R_SPECIAL = 2, R_FAIL = 3 };
enum { F_NONE, F_ERRTEST, F_NEWTON, F_STEPSIZE, F_SINGULAR, F_NONFINITE, F_CRAWL };

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

typedef int (*cb_res)(double, const double *, const double *, double *);
typedef int (*cb_jac)(double, const double *, const double *, double, double *);
typedef int (*cb_roots)(double, const double *, const double *, double *);

/* the loop's view of one run: the state, and its work vectors in the scratch buffer */
typedef struct {
  cbdf_state *s;
  int64_t n;
  double *phi, *ewt_n, *ewt, *ewt_err, *ee, *delta, *ypred, *yppred, *ytmp, *yptmp,
         *fallback, *rhs, *lu, *req, *ceq;
  int64_t *piv;
} ctx_t;

/* ------------------------------------------------------------------ the problem */
static int residual(ctx_t *c, double t, const double *y, const double *yp, double *F) {
  cbdf_state *s = c->s;
  s->n_residuals++;
  if (s->mode == 1) return ((cb_res)s->residual_fn)(t, y, yp, F);
  int64_t nres = s->n_res, nsz = s->n_state_rows, nl = s->n_links;
  double *out = s->model_out;
  ((cbdf_genfn)s->residual_fn)(t, y, s->par, s->m, out, s->work);
  const int64_t *sz = s->state_z, *ls = s->link_s, *ld = s->link_d;
  for (int64_t i = 0; i < nres; ++i) F[i] = out[i];
  for (int64_t i = 0; i < nsz; ++i) F[nres + i] = yp[sz[i]] - out[nres + i];
  int64_t r0 = nres + nsz;
  for (int64_t i = 0; i < nl; ++i) F[r0 + i] = yp[ls[i]] - y[ld[i]];
  return 0;
}

/* dense row-major dF/dy + cj dF/dy' */
static void jacobian(ctx_t *c, double t, const double *y, const double *yp, double cj,
                     double *J) {
  cbdf_state *s = c->s; int64_t n = c->n;
  s->n_jacobians++;
  if (s->mode == 1) { ((cb_jac)s->jacobian_fn)(t, y, yp, cj, J); return; }
  double *v = s->jac_values;
  ((cbdf_genfn)s->jacobian_fn)(t, y, s->par, s->m, v, s->work);
  const int64_t *jr = s->jac_rows, *jc = s->jac_cols;
  const double *js = s->jac_sign;
  if (s->sparse) {     /* into the sparse LU's values, J unused */
    sparse_jacobian(s->splu, v, js, s->n_jac, s->n_state_rows, s->n_links, cj);
    return;
  }
  memset(J, 0, sizeof(double) * n * n);
  for (int64_t e = 0; e < s->n_jac; ++e) J[jr[e] * n + jc[e]] += js[e] * v[e];
  int64_t nres = s->n_res, nsz = s->n_state_rows, nl = s->n_links;
  const int64_t *sz = s->state_z, *ls = s->link_s, *ld = s->link_d;
  for (int64_t i = 0; i < nsz; ++i) J[(nres + i) * n + sz[i]] += cj;
  int64_t r0 = nres + nsz;
  for (int64_t i = 0; i < nl; ++i) {
    J[(r0 + i) * n + ls[i]] += cj;
    J[(r0 + i) * n + ld[i]] -= 1.0;
  }
}

/* the oriented zero-crossing functions of acausal.runtime.modes (plus their offsets) */
static void roots(ctx_t *c, double t, const double *y, const double *yp, double *r) {
  cbdf_state *s = c->s;
  if (s->mode == 1) { ((cb_roots)s->roots_fn)(t, y, yp, r); return; }
  int64_t nrel = s->n_rel, ndisc = s->n_disc;
  double *v = s->root_values, *sc = s->root_scales;
  const double *p = s->par, *m = s->m;
  double *w = s->work;
  ((cbdf_genfn)s->roots_fn)(t, y, p, m, v, w);
  const double *sg = s->root_sign, *sd = s->root_side,
               *nom = s->root_nominal, *timed = s->timed,
               *off = s->root_offset;
  if (nrel) {
    ((cbdf_genfn)s->scales_fn)(t, y, p, m, sc, w);
    for (int64_t k = 0; k < nrel; ++k)
      r[k] = sg[k] * v[k] + sd[k] * (ZERO_RTOL * fabs(sc[k]) + ZERO_NOMINAL * nom[k]);
  }
  for (int64_t j = 0; j < ndisc; ++j) {
    double u = v[nrel + j], nn = m[nrel + j], tol = ZERO_RTOL * (fabs(u) + 1.0);
    r[nrel + 2 * j] = u - nn + tol;
    r[nrel + 2 * j + 1] = nn + 1.0 - u + (timed[nrel + j] != 0.0 ? tol : -tol);
  }
  for (int64_t k = 0; k < s->n_roots; ++k) r[k] += off[k];
}

/* ------------------------------------------------------------------ linear algebra */
static int factor(ctx_t *c, double *J) {
  cbdf_state *s = c->s;
  if (s->sparse) return sparse_factor(s->splu);
  int equil = 0;
  int k = dense_factor(J, c->lu, c->piv, c->req, c->ceq, c->n, &equil);
  s->equilibrated = equil;
  return k;
}

static void solve(ctx_t *c, double *b) {
  cbdf_state *s = c->s;
  if (s->sparse) { sparse_solve(s->splu, b); return; }
  dense_solve(c->lu, c->piv, s->equilibrated ? c->req : 0, c->ceq, c->n, b);
}

static double wrms(const double *v, const double *w, int64_t n) {
  double sum = 0.0;
  for (int64_t i = 0; i < n; ++i) { double x = v[i] * w[i]; sum += x * x; }
  return sqrt(sum / n);
}

/* ------------------------------------------------------------------ corrector */
/* setup: 0 or a failure kind */
static int setup(ctx_t *c, double t, const double *y, const double *yp) {
  cbdf_state *s = c->s;
  double *J = s->scratch;   /* the first n*n of scratch */
  jacobian(c, t, y, yp, s->cj, J);
  s->n_lu++;
  int k = factor(c, J);
  if (k) {
    s->fail_tj = t; s->fail_cj = s->cj;
    memcpy(s->fail_y, y, sizeof(double) * c->n);
    memcpy(s->fail_yp, yp, sizeof(double) * c->n);
    return k;
  }
  s->cjold = s->cj; s->cjratio = 1.0; s->ss = 20.0; s->force_setup = 0;
  return 0;
}

/* one simplified-Newton iteration: 1 converged (ee), 0 failed; *fb: a fallback iterate
   (the test without the self-scaled components passed) is in c->fallback */
static int iterate(ctx_t *c, double tnew, double cj, int *fb, int *have_last) {
  cbdf_state *s = c->s; int64_t n = c->n;
  double *ee = c->ee, *delta = c->delta, *w = c->ewt_n;
  int rest = s->any_self_scaled != 0;
  double scale = s->cjratio != 1.0 ? 2.0 / (1.0 + s->cjratio) : 1.0;
  double first = 0.0, first_rest = 0.0, ss0 = s->ss;
  *fb = 0; *have_last = 0;
  for (int m = 0; m < MAXCOR; ++m) {
    if (m == 0) residual(c, tnew, c->ypred, c->yppred, delta);
    else {
      for (int64_t i = 0; i < n; ++i) {
        c->ytmp[i] = c->ypred[i] + ee[i];
        c->yptmp[i] = c->yppred[i] + cj * ee[i];
      }
      residual(c, tnew, c->ytmp, c->yptmp, delta);
    }
    s->n_newton++;
    solve(c, delta);
    for (int64_t i = 0; i < n; ++i) delta[i] *= -scale;
    if (m == 0) memcpy(ee, delta, sizeof(double) * n);
    else for (int64_t i = 0; i < n; ++i) ee[i] += delta[i];
    double delnrm = wrms(delta, w, n);
    if (!isfinite(delnrm)) { *fb = 0; return 0; }
    if (m == 0) {
      first = delnrm;
      double ssm = s->ss > SS_FLOOR ? s->ss : SS_FLOOR;
      if (delnrm <= TINY * EPCON || ssm * delnrm <= EPCON) return 1;
    } else {
      double rate = first > 0 ? pow(delnrm / first, 1.0 / m) : 0.0;
      if (rate > RATEMAX) goto fail;
      s->ss = rate / (1.0 - rate);
      if (s->ss * delnrm <= EPCON) return 1;
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
  for (int64_t i = 0; i < n; ++i) (s->weighted)[i] = delta[i] * w[i];
  *have_last = 1;
  return 0;
}

/* the correction ee of the step to tnew: 0, -1 (Newton failure) or a setup failure kind */
static int corrector(ctx_t *c, double tnew) {
  cbdf_state *s = c->s; int64_t n = c->n;
  double cj = s->cj;
  s->cjratio = cj / s->cjold;
  double lo = (1.0 - XRATE) / (1.0 + XRATE);
  int call_setup = s->force_setup || !(lo <= s->cjratio && s->cjratio <= 1.0 / lo);
  if (cj != s->cjlast) s->ss = 100.0;
  int fresh = 0;
  for (;;) {
    if (call_setup) {
      int k = setup(c, tnew, c->ypred, c->yppred);
      if (k) return k;
      fresh = 1;
    }
    int fb, have_last;
    if (iterate(c, tnew, cj, &fb, &have_last)) {
      if (s->cjratio != 1.0 && s->any_algebraic) {
        /* one unscaled correction: the algebraic rows do not contain cj */
        for (int64_t i = 0; i < n; ++i) {
          c->ytmp[i] = c->ypred[i] + c->ee[i];
          c->yptmp[i] = c->yppred[i] + cj * c->ee[i];
        }
        s->n_newton++;
        residual(c, tnew, c->ytmp, c->yptmp, c->delta);
        solve(c, c->delta);
        int fin = 1;
        for (int64_t i = 0; i < n; ++i) if (!isfinite(c->delta[i])) { fin = 0; break; }
        if (fin) for (int64_t i = 0; i < n; ++i) c->ee[i] -= c->delta[i];
      }
      return 0;
    }
    if (fresh) {
      if (fb) { memcpy(c->ee, c->fallback, sizeof(double) * n); return 0; }
      s->has_fail = have_last;
      return -1;
    }
    call_setup = 1;
  }
}

/* ------------------------------------------------------------------ step */

static double set_coeffs(ctx_t *c) {
  cbdf_state *s = c->s; int64_t n = c->n;
  int64_t kk = s->kk; double hh = s->hh;
  double *psi = s->psi, *alpha = s->alpha, *beta = s->beta,
         *sigma = s->sigma, *gamma = s->gamma;
  if (hh != s->hused || kk != s->kused) s->ns = 0;
  s->ns = s->ns + 1 < s->kused + 2 ? s->ns + 1 : s->kused + 2;
  if (kk + 1 >= s->ns) {
    beta[0] = alpha[0] = sigma[0] = 1.0; gamma[0] = 0.0;
    double temp1 = hh;
    for (int64_t i = 1; i <= kk; ++i) {
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
  double alphas = s->alphas[kk], alpha0 = 0.0;
  for (int64_t i = 0; i < kk; ++i) alpha0 -= alpha[i];
  s->cjlast = s->cj;
  s->cj = -alphas / hh;
  double a = fabs(alpha[kk] + alphas - alpha0), ck = a > alpha[kk] ? a : alpha[kk];
  for (int64_t i = s->ns; i <= kk; ++i) {
    double *p = c->phi + i * n;
    for (int64_t j = 0; j < n; ++j) p[j] *= beta[i];
  }
  return ck;
}

static void restore(ctx_t *c, double saved_t) {
  cbdf_state *s = c->s; int64_t n = c->n, kk = s->kk;
  s->tn = saved_t;
  for (int64_t j = 1; j <= kk; ++j) s->psi[j - 1] = s->psi[j] - s->hh;
  for (int64_t i = s->ns; i <= kk; ++i) {
    double *p = c->phi + i * n;
    for (int64_t j = 0; j < n; ++j) p[j] /= s->beta[i];
  }
}

static void shrink(ctx_t *c, double rr) {
  cbdf_state *s = c->s; int64_t n = c->n;
  s->hh *= rr;
  if (s->nst == 0) {
    s->psi[0] = s->hh;
    for (int64_t j = 0; j < n; ++j) c->phi[n + j] *= rr;
  }
}

static void update_weights(ctx_t *c) {
  cbdf_state *s = c->s; int64_t n = c->n; double rtol = s->rtol;
  const double *atol = s->atol, *ssm = s->ss_mask, *em = s->err_mask;
  for (int64_t i = 0; i < n; ++i) {
    c->ewt_n[i] = 1.0 / (rtol * fabs(c->phi[i]) + atol[i]);
    c->ewt[i] = c->ewt_n[i] * ssm[i];
    c->ewt_err[i] = c->ewt[i] * em[i];
  }
}

static void next_step(ctx_t *c, double err_knew) {
  cbdf_state *s = c->s;
  double rr = pow(2.0 * err_knew + 1e-4, -1.0 / (s->kk + 1));
  if (rr >= 2.0) s->hh = fmin(2.0 * s->hh, s->max_step);
  else if (rr <= 1.0) s->hh *= fmax(0.5, fmin(0.9, rr));
}

static void complete_step(ctx_t *c, double err_k, double err_km1, int64_t knew) {
  cbdf_state *s = c->s; int64_t n = c->n;
  double *ee = c->ee, *phi = c->phi;
  int64_t kk = s->kk;
  s->nst++; s->n_steps++; s->orders[kk]++;
  int64_t kdiff = kk - s->kused;
  s->kused = kk; s->hused = s->hh;
  if (knew == kk - 1 || kk >= s->kmax) s->phase = 1;
  if (s->phase == 0) {
    if (s->nst > 1) {
      s->kk = kk + 1;
      s->hh = fmin(2.0 * s->hh, s->max_step);
    }
  } else {
    int action = 0;   /* 0 maintain, 1 raise, -1 lower */
    double err_kp1 = 0.0;
    if (knew == kk - 1) action = -1;
    else if (kk >= s->kmax || kk + 1 >= s->ns || kdiff == 1) action = 0;
    else {
      double *p1 = phi + (kk + 1) * n, sum = 0.0;
      for (int64_t i = 0; i < n; ++i) {
        double x = (ee[i] - p1[i]) * c->ewt_err[i];
        sum += x * x;
      }
      err_kp1 = sqrt(sum / n) / (kk + 2);
      double terr_k = (kk + 1) * err_k, terr_kp1 = (kk + 2) * err_kp1;
      if (kk == 1) action = terr_kp1 >= 0.5 * terr_k ? 0 : 1;
      else if (kk * err_km1 <= fmin(terr_k, terr_kp1)) action = -1;
      else if (terr_kp1 >= terr_k) action = 0;
      else action = 1;
    }
    double err_knew = err_k;
    if (action == 1) { s->kk = kk + 1; err_knew = err_kp1; }
    else if (action == -1) { s->kk = kk - 1; err_knew = err_km1; }
    next_step(c, err_knew);
  }
  int64_t ku = s->kused;
  if (ku < s->max_order) memcpy(phi + (ku + 1) * n, ee, sizeof(double) * n);
  for (int64_t j = 0; j < n; ++j) phi[ku * n + j] += ee[j];
  for (int64_t k = ku - 1; k >= 0; --k)
    for (int64_t j = 0; j < n; ++j) phi[k * n + j] += phi[(k + 1) * n + j];
  s->t_prev = s->tn - s->hused;
  double *le = s->last_err, *yp = s->yp;
  for (int64_t i = 0; i < n; ++i) {
    le[i] = ee[i] * c->ewt_err[i];
    yp[i] = c->yppred[i] + s->cj * ee[i];
  }
  s->has_last = 1;
}

/* count a failed attempt that is the algebraic unknowns' alone (bdf.py's _count_crawl):
   the largest weighted component is algebraic and the differential ones pass alone */
static void count_crawl(ctx_t *c, const double *wt, double ck) {
  cbdf_state *s = c->s; int64_t n = c->n;
  const double *alg = s->alg_mask;
  int64_t top = -1; double big = -1.0, sum = 0.0; int alone = s->any_algebraic != 0;
  for (int64_t i = 0; alone && i < n; ++i) {
    double a = fabs(wt[i]);
    if (!isfinite(a)) alone = 0;
    else {
      if (a > big) { big = a; top = i; }
      if (alg[i] == 0.0) sum += a * a;
    }
  }
  alone = alone && top >= 0 && alg[top] != 0.0 && ck * sqrt(sum / n) <= 1.0;
  s->crawl = alone ? s->crawl + 1 : 0;
}

/* one accepted step: 0, or a failure kind (F_...) */
static int step(ctx_t *c) {
  cbdf_state *s = c->s; int64_t n = c->n;
  int ncf = 0, nef = 0, nsing = 0;
  double saved_t = s->tn;
  if (s->crawl >= s->max_crawl) {
    s->crawl = 0; s->fail_t = saved_t; s->fail_h = s->hh;
    return F_CRAWL;
  }
  s->has_fail = 0;
  update_weights(c);
  double ck, err_k, err_km1; int64_t knew;
  for (;;) {
    s->hh = fmin(s->hh, s->max_step);
    double tstop = s->t_stop, remaining = tstop - saved_t;
    double hmin = 16.0 * DBL_EPSILON *
                  fmax(fmax(fabs(s->tn), fabs(s->hused)), 1e-300);
    int landing = isfinite(tstop) && s->hh >= remaining - 64 * DBL_EPSILON * fabs(tstop);
    if (landing) {
      if (remaining <= hmin) { s->t_prev = saved_t; s->tn = tstop; return -1; }
      s->hh = remaining;
    }
    if (s->hh < hmin) {
      s->fail_t = saved_t; s->fail_h = s->hh;
      return F_STEPSIZE;
    }
    ck = set_coeffs(c);
    double tnew = landing ? tstop : saved_t + s->hh;
    s->tn = tnew;
    int64_t kk = s->kk;
    const double *gamma = s->gamma;
    for (int64_t j = 0; j < n; ++j) {
      double sum = c->phi[j], sp = 0.0;
      for (int64_t i = 1; i <= kk; ++i) {
        sum += c->phi[i * n + j];
        sp += gamma[i] * c->phi[i * n + j];
      }
      c->ypred[j] = sum; c->yppred[j] = sp;
    }
    int k = corrector(c, tnew);
    if (k == F_SINGULAR || k == F_NONFINITE) {
      restore(c, saved_t);
      if (++nsing >= MAXSING) { s->fail_t = saved_t; s->fail_h = s->hh; return k; }
      shrink(c, 0.25); s->force_setup = 1; continue;
    }
    if (k == -1) {
      restore(c, saved_t);
      s->n_newton_fails++; ncf++; s->phase = 1;
      if (s->has_fail) count_crawl(c, s->weighted, 1.0); else s->crawl = 0;
      if (ncf >= MAXNCF) {
        s->fail_t = saved_t; s->fail_h = s->hh;
        return F_NEWTON;
      }
      shrink(c, 0.25); s->force_setup = 1; continue;
    }
    /* the error test (IDATestError) */
    const double *w = c->ewt_err, *sigma = s->sigma;
    double enorm_k = wrms(c->ee, w, n);
    err_k = sigma[kk] * enorm_k;
    double terr_k = (kk + 1) * err_k;
    err_km1 = 0.0; knew = kk;
    if (kk > 1) {
      double *d = c->delta, sum = 0.0;
      for (int64_t j = 0; j < n; ++j) {
        d[j] = c->phi[kk * n + j] + c->ee[j];
        double x = d[j] * w[j];
        sum += x * x;
      }
      err_km1 = sigma[kk - 1] * sqrt(sum / n);
      double terr_km1 = kk * err_km1;
      if (kk > 2) {
        sum = 0.0;
        for (int64_t j = 0; j < n; ++j) {
          d[j] += c->phi[(kk - 1) * n + j];
          double x = d[j] * w[j];
          sum += x * x;
        }
        double terr_km2 = (kk - 1) * sigma[kk - 2] * sqrt(sum / n);
        if (fmax(terr_km1, terr_km2) <= terr_k) knew = kk - 1;
      } else if (terr_km1 <= 0.5 * terr_k) knew = kk - 1;
    }
    if (ck * enorm_k <= 1.0) break;
    restore(c, saved_t);
    s->n_error_fails++; nef++;
    double *wt = s->weighted;
    for (int64_t j = 0; j < n; ++j) wt[j] = c->ee[j] * w[j];
    s->has_fail = 1; s->phase = 1;
    count_crawl(c, wt, ck);
    if (nef >= MAXNEF) {
      s->fail_t = saved_t; s->fail_h = s->hh;
      return F_ERRTEST;
    }
    s->kmax = s->max_order;
    if (s->nst == 0 && nef <= 3) {
      double rr = 0.9 * pow(2.0 * err_k + 1e-4, -0.5);
      shrink(c, fmax(1e-3, fmin(0.9, rr)));
    } else if (nef == 1) {
      s->kk = knew;
      double err_knew = knew == kk ? err_k : err_km1;
      double rr = 0.9 * pow(2.0 * err_knew + 1e-4, -1.0 / (s->kk + 1));
      shrink(c, fmax(0.25, fmin(0.9, rr)));
    } else {
      double rr = 0.25;
      if (kk == 1) rr = fmax(1e-3, fmin(0.25, 0.9 * pow(2.0 * err_k + 1e-4, -0.5)));
      s->kk = nef == 2 ? knew : 1;
      shrink(c, rr);
    }
  }
  complete_step(c, err_k, err_km1, knew);
  return 0;
}

/* ------------------------------------------------------------------ output */
/* y and y' at t from the BDF's interpolating polynomial (the Python loop's interpolate) */
void cbdf_interpolate(const cbdf_state *s, double t, double *y, double *yp) {
  int64_t n = s->n, kord = s->kused > 1 ? s->kused : 1;
  const double *phi = s->phi, *psi = s->psi;
  double delt = t - s->tn;
  double cc = 1.0, d = 0.0, gam = delt / psi[0];
  memcpy(y, phi, sizeof(double) * n);
  memset(yp, 0, sizeof(double) * n);
  for (int64_t j = 1; j <= kord; ++j) {
    d = d * gam + cc / psi[j - 1];
    cc = cc * gam;
    gam = (delt + psi[j - 1]) / psi[j];
    const double *p = phi + j * n;
    for (int64_t i = 0; i < n; ++i) { y[i] += cc * p[i]; yp[i] += d * p[i]; }
  }
}

static int emit(ctx_t *c, double t, const double *y, const double *yp) {
  cbdf_state *s = c->s; int64_t n = c->n;
  if (s->count >= s->capacity) return 0;
  int64_t k = s->count++;
  s->out_t[k] = t;
  double *oy = s->out_y + k * n, *oyp = s->out_yp + k * n;
  if (y) { memcpy(oy, y, sizeof(double) * n); memcpy(oyp, yp, sizeof(double) * n); }
  else cbdf_interpolate(s, t, oy, oyp);
  return 1;
}

/* the output of the accepted interval (t_prev, t]; 0 when the buffer filled first */
static int emit_step(ctx_t *c) {
  cbdf_state *s = c->s;
  if (s->all_steps) return emit(c, s->tn, c->phi, s->yp);
  const double *ev = s->t_eval;
  while (s->i_eval < s->n_eval && ev[s->i_eval] <= s->tn) {
    double te = ev[s->i_eval];
    if (te >= s->t_prev && !emit(c, te, 0, 0)) return 0;
    s->i_eval++;
  }
  return 1;
}

/* ------------------------------------------------------------------ the loop */
int64_t cbdf_state_size(void) { return (int64_t)sizeof(cbdf_state); }

/* the digest of the sources this library was built from (setup.py defines it) */
#ifndef CBDF_SOURCE_DIGEST
#define CBDF_SOURCE_DIGEST ""
#endif
const char *cbdf_source_digest(void) { return CBDF_SOURCE_DIGEST; }

/* steps until something needs Python; returns R_BUDGET, R_FULL, R_SPECIAL or R_FAIL */
int cbdf_run(cbdf_state *s) {
  ctx_t c;
  int64_t n = s->n;
  c.s = s; c.n = n;
  c.phi = s->phi;
  /* after the dense matrix (none with the sparse LU) */
  double *w = s->scratch + (s->sparse ? 0 : n * n);
  c.ewt_n = w; c.ewt = w + n; c.ewt_err = w + 2 * n; c.ee = w + 3 * n; c.delta = w + 4 * n;
  c.ypred = w + 5 * n; c.yppred = w + 6 * n; c.ytmp = w + 7 * n; c.yptmp = w + 8 * n;
  c.fallback = w + 9 * n; c.rhs = w + 10 * n; c.req = w + 11 * n; c.ceq = w + 12 * n;
  c.lu = s->lu; c.piv = s->piv;
  int64_t nr = s->n_roots;
  double *g = s->g, *gprev = s->g_prev, *ref = s->sign_ref, *off = s->root_offset;
  s->pending = 0;
  for (;;) {
    if (s->budget <= 0) return R_BUDGET;
    if (s->all_steps && s->count >= s->capacity) return R_FULL;
    int k = step(&c);
    if (k == -1) return R_SPECIAL;       /* landed on the stop time without a step */
    if (k) { s->fail_kind = k; return R_FAIL; }
    s->budget--;
    if (s->tn == s->t_stop) return R_SPECIAL;
    if (nr) {
      roots(&c, s->tn, c.phi, s->yp, g);
      int crossed = 0, finite = 1;
      for (int64_t i = 0; i < nr; ++i) {
        if (!isfinite(g[i])) finite = 0;
        if (ref[i] != 0.0 && g[i] * ref[i] <= 0.0) crossed = 1;
      }
      if (crossed || !finite) return R_SPECIAL;   /* Python locates and handles it */
      for (int64_t i = 0; i < nr; ++i) {
        if (ref[i] == 0.0) ref[i] = g[i] > 0 ? 1.0 : (g[i] < 0 ? -1.0 : 0.0);
        gprev[i] = g[i];
      }
      /* offsets of items armed at zero end once they have left it on their own side */
      if (s->mode == 0)
        for (int64_t i = 0; i < nr; ++i)
          if (off[i] != 0.0 && g[i] - off[i] >= 0.0) off[i] = 0.0;
    }
    int due = s->dyn_longs && dyn_due(s->dyn_longs, s->dyn_doubles,
                                      s->mode == 0 ? s->jacobian_fn : 0, s->tn, c.phi,
                                      s->par, s->m, s->jac_values, s->work, s->n_jac);
    if (!emit_step(&c)) { s->pending = 1; return R_FULL; }
    if (due) return R_FULL;            /* Python re-chooses the states, then goes on */
  }
}
