/* The algebraic unknowns by Newton and the modes of the relations, of an exported model
   (runtime/modes.py), and the state derivatives, that the engine (engine.c) and the event
   iteration of the discrete part (discrete.c) share.

   * G(t, z) = 0 is solved for z[alg] by Newton with the generated Jacobian, warm started
     from the last solution; converged when every update is below NEWTON_STOP of
     |z_i| + nominal_i; the initial system is solved by the same Newton over all z.
     Dense linear algebra (LU with partial pivoting, Golub & Van Loan, Alg. 3.4.1): the
     models that are exported as FMUs are small, and a dense factorization is simple
     and deterministic.
   * Event indicators are the oriented zero-crossing functions of runtime/modes.py:
     r_k = s_k g_k + h_k >= 0 while the frozen relation value agrees with the solution,
     with h_k the relation's zero tolerance on its own scale.
   * Settling: every relation takes its value just after t (ac_settle_all), or only
     those the solution clearly contradicts (ac_settle_contradicted). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <stdio.h>
#include "acausal_fmu.h"

#define ZERO_NOMINAL 1e-12
#define NEWTON_STOP 1e-11
#define NEWTON_ITER 60

void *ac_zalloc(int n, size_t size) { return calloc(n > 0 ? n : 1, size); }

/* -- dense LU with partial pivoting (row-major A, n x n) --------------------------------- */
int ac_lu(double *A, int n, int *piv) {
    for (int k = 0; k < n; ++k) {
        int p = k;
        double big = fabs(A[k * n + k]);
        for (int i = k + 1; i < n; ++i)
            if (fabs(A[i * n + k]) > big) { big = fabs(A[i * n + k]); p = i; }
        piv[k] = p;
        if (!(big > 0.0)) return -1;                 /* singular (or NaN) */
        if (p != k)
            for (int j = 0; j < n; ++j) {
                double tmp = A[k * n + j]; A[k * n + j] = A[p * n + j]; A[p * n + j] = tmp;
            }
        for (int i = k + 1; i < n; ++i) {
            double l = A[i * n + k] / A[k * n + k];
            A[i * n + k] = l;
            if (l != 0.0)
                for (int j = k + 1; j < n; ++j) A[i * n + j] -= l * A[k * n + j];
        }
    }
    return 0;
}

void ac_lu_solve(const double *A, int n, const int *piv, double *b) {
    for (int k = 0; k < n; ++k) {
        if (piv[k] != k) { double tmp = b[k]; b[k] = b[piv[k]]; b[piv[k]] = tmp; }
        for (int i = k + 1; i < n; ++i) b[i] -= A[i * n + k] * b[k];
    }
    for (int k = n - 1; k >= 0; --k) {
        for (int j = k + 1; j < n; ++j) b[k] -= A[k * n + j] * b[j];
        b[k] /= A[k * n + k];
    }
}

/* -- Newton on a square system: the algebraic unknowns, or the initial system ------------- */
static int eval_rows(ac_state *s, const ac_system *sys, double *F) {
    const ac_model *md = s->md;
    if (md->residual(s->t, s->z, s->p, s->m, s->rows, s->wf) && md->n_res) {
        for (int i = 0; i < md->n_res; ++i) if (!isfinite(s->rows[i])) return -1;
    }
    for (int i = 0; i < md->n_res; ++i) F[i] = s->rows[i];
    if (sys->initial && md->n_init) {
        md->init_residual(s->t, s->z, s->p, s->m, s->irows, s->wi);
        for (int i = 0; i < md->n_init; ++i) {
            F[md->n_res + i] = s->irows[md->init_keep[i]];
            if (!isfinite(F[md->n_res + i])) return -1;
        }
        /* z[k] - start: the start value the importer set (the Jacobian entry is 1) */
        for (int j = 0; j < md->n_start; ++j)
            F[md->n_res + md->start_row[j]] = s->z[md->start_z[j]] - s->x_start[j];
    }
    return 0;
}

static int eval_dense(ac_state *s, const ac_system *sys, double *A) {
    const ac_model *md = s->md;
    int n = sys->n;
    memset(A, 0, (size_t)n * n * sizeof(double));
    md->jacobian(s->t, s->z, s->p, s->m, s->jac, s->wf);
    for (int e = 0; e < md->n_jac; ++e) {
        int r = md->jac_rows[e], c = md->jac_cols[e];
        int col = sys->initial ? c : s->algpos[c];
        if (r < md->n_res && col >= 0) A[r * n + col] += s->jac[e];
    }
    if (sys->initial && md->n_init) {
        md->init_jacobian(s->t, s->z, s->p, s->m, s->ijac, s->wi);
        for (int e = 0; e < md->n_ijac; ++e) {
            int r = s->initpos[md->ijac_rows[e]];
            if (r >= 0) A[r * n + md->ijac_cols[e]] += s->ijac[e];
        }
    }
    for (int k = 0; k < n * n; ++k) if (!isfinite(A[k])) return -1;
    return 0;
}

static double norm2(const double *v, int n) {
    double a = 0.0;
    for (int i = 0; i < n; ++i) a += v[i] * v[i];
    return sqrt(a);
}

/* Damped Newton: full steps while the residual norm falls, else halved (Armijo). */
int ac_newton(ac_state *s, const ac_system *sys) {
    int n = sys->n;
    double *F = s->rhs, *dz = s->zsave;
    double *trial = (double *)malloc(sizeof(double) * (n > 0 ? n : 1));
    int status = -1;
    if (!trial) return -1;
    double prev = INFINITY;
    if (eval_rows(s, sys, F)) goto done;
    for (int it = 0; it < NEWTON_ITER; ++it) {
        double f0 = norm2(F, n), step = 0.0;
        if (eval_dense(s, sys, s->dense) || ac_lu(s->dense, n, s->piv)) goto done;
        for (int i = 0; i < n; ++i) dz[i] = -F[i];
        ac_lu_solve(s->dense, n, s->piv, dz);
        for (int i = 0; i < n; ++i) {
            int k = sys->cols[i];
            double w = fabs(dz[i]) / (fabs(s->z[k]) + s->md->nominal[k]);
            if (w > step) step = w;
            trial[i] = s->z[k];
        }
        if (!isfinite(step)) goto done;
        if (step <= NEWTON_STOP || (step < 1e-8 && step >= 0.5 * prev)) {
            /* converged, or stalled at round-off (the updates no longer fall): the
               full step, without a line search that round-off would mislead */
            for (int i = 0; i < n; ++i) s->z[sys->cols[i]] = trial[i] + dz[i];
            status = 0;
            goto done;
        }
        double lam = 1.0;
        for (int back = 0; back < 12; ++back, lam *= 0.5) {
            for (int i = 0; i < n; ++i) s->z[sys->cols[i]] = trial[i] + lam * dz[i];
            if (eval_rows(s, sys, F) == 0 && (norm2(F, n) <= (1.0 - 1e-4 * lam) * f0
                                              || back == 11 || f0 == 0.0))
                break;
        }
        prev = step;
    }
done:
    free(trial);
    return status;
}

int ac_solve_algebraic(ac_state *s) {
    const ac_model *md = s->md;
    if (s->solved) return 0;
    s->expanded = 0;
    if (md->n_alg) {
        ac_system sys = {md->n_alg, md->alg_index, 0};
        if (ac_newton(s, &sys)) {
            snprintf(s->message, sizeof s->message,
                     "the algebraic equations have no solution at t = %.10g (Newton failed)",
                     s->t);
            return -1;
        }
    }
    if (md->residual(s->t, s->z, s->p, s->m, s->rows, s->wf)) {
        snprintf(s->message, sizeof s->message,
                 "the model equations are not finite at t = %.10g", s->t);
        return -1;
    }
    s->solved = 1;
    return 0;
}

int ac_derivatives(ac_state *s) {
    const ac_model *md = s->md;
    if (ac_solve_algebraic(s)) return -1;
    for (int i = 0; i < md->n_state_z; ++i) s->xdot[i] = s->rows[md->n_res + i];
    for (int i = md->n_state_z; i < md->n_x; ++i)
        s->xdot[i] = s->z[md->link_d[i - md->n_state_z]];
    return 0;
}

/* -- relations ---------------------------------------------------------------------------- */
int ac_items(const ac_model *md) { return md->n_rel + md->n_disc; }

void ac_values(ac_state *s, double t, double *v) {
    if (ac_items(s->md)) s->md->roots(t, s->z, s->p, s->m, v, s->wf);
}

double ac_rel_tol(ac_state *s, int k) {
    return ZERO_RTOL * fabs(s->scl[k]) + ZERO_NOMINAL * s->md->rel_nominal[k];
}

static int truth(const ac_model *md, int k, double g) {
    if (md->upward[k]) return md->strict[k] ? g > 0 : g >= 0;
    return md->strict[k] ? g < 0 : g <= 0;
}

int ac_oriented(ac_state *s, double *r) {
    const ac_model *md = s->md;
    int R = md->n_rel;
    if (ac_solve_algebraic(s)) return -1;
    ac_values(s, s->t, s->rts);
    if (R) md->scales(s->t, s->z, s->p, s->m, s->scl, s->wf);
    for (int k = 0; k < R; ++k) {
        int holds = s->m[k] > 0.5;
        int up = holds ? md->upward[k] : !md->upward[k];
        int closed = (holds != md->strict[k]) || md->timed[k];
        r[k] = (up ? 1.0 : -1.0) * s->rts[k] + (closed ? 1.0 : -1.0) * ac_rel_tol(s, k);
    }
    for (int j = 0; j < md->n_disc; ++j) {
        double u = s->rts[R + j], n = s->m[R + j], tu = ZERO_RTOL * (fabs(u) + 1.0);
        r[R + 2 * j] = u - n + tu;
        r[R + 2 * j + 1] = n + 1.0 - u + (md->timed[R + j] ? tu : -tu);
    }
    for (int k = 0; k < R + 2 * md->n_disc; ++k) r[k] += s->offset[k];
    return 0;
}

/* At a (re)start an item settled at zero by its rate may sit a hair on the other side of
   zero; its indicator is raised by that much until a step ends with the item on its own
   side (runtime/modes.py, DiscreteState.arm and release). */
void ac_arm(ac_state *s) {
    const ac_model *md = s->md;
    int R = md->n_rel, nr = R + 2 * md->n_disc;
    double *r = (double *)ac_zalloc(nr, sizeof(double));
    if (!r) return;
    memset(s->offset, 0, nr * sizeof(double));
    if (nr && ac_oriented(s, r) == 0)
        for (int k = 0; k < nr; ++k) {
            double tol = k < R ? ac_rel_tol(s, k)
                               : ZERO_RTOL * (fabs(s->rts[R + (k - R) / 2]) + 1.0);
            if (r[k] < 0 && -r[k] <= 8.0 * tol) s->offset[k] = -2.0 * r[k];
        }
    free(r);
}

void ac_release(ac_state *s) {
    const ac_model *md = s->md;
    int nr = md->n_rel + 2 * md->n_disc, any = 0;
    for (int k = 0; k < nr; ++k) any |= s->offset[k] != 0.0;
    if (!any) return;
    double *r = (double *)ac_zalloc(nr, sizeof(double));
    if (r && ac_oriented(s, r) == 0)
        for (int k = 0; k < nr; ++k)
            if (r[k] - s->offset[k] >= 0) s->offset[k] = 0.0;
    free(r);
}

/* d/dt of every item's value along the solution, by a forward difference on a step small
   on the solution's own scale (runtime/model.py, CompiledModel.rates). */
static int rates(ac_state *s, double *rate) {
    const ac_model *md = s->md;
    int n = md->n_z, ni = ac_items(md);
    double *z0 = (double *)malloc(sizeof(double) * (n + ni + 1)), *v0 = z0 + n;
    double t0 = s->t, fastest = 0.0, dt = 1e-8 * (1.0 + fabs(t0));
    if (!z0) return -1;
    if (ac_derivatives(s)) { free(z0); return -1; }
    memcpy(z0, s->z, n * sizeof(double));
    ac_values(s, t0, v0);
    for (int i = 0; i < md->n_x; ++i) {
        int k = md->state_index[i];
        double w = fabs(s->xdot[i]) / (fabs(s->z[k]) + md->nominal[k]);
        if (w > fastest) fastest = w;
    }
    if (fastest * dt > 1e-8) dt = 1e-8 / fastest;
    for (int i = 0; i < md->n_x; ++i) s->z[md->state_index[i]] += dt * s->xdot[i];
    s->t = t0 + dt;
    s->solved = 0;
    int bad = ac_solve_algebraic(s);
    ac_values(s, s->t, rate);
    for (int k = 0; k < ni; ++k) rate[k] = bad ? 0.0 : (rate[k] - v0[k]) / dt;
    memcpy(s->z, z0, n * sizeof(double));
    s->t = t0;
    s->solved = 0;
    free(z0);
    return ac_solve_algebraic(s);
}

/* Every item takes its value just after t: the sign of g where it is clearly non-zero,
   else the side its rate chooses, else (no rate) the relation's value at exactly zero.
   With rates the point is a solution (the algebraic unknowns solved first); without,
   the values are taken where z is (the start values, before the initial system). */
int ac_settle_all(ac_state *s, int with_rates) {
    const ac_model *md = s->md;
    int R = md->n_rel, ni = ac_items(md), changed = 0;
    double *rate = (double *)ac_zalloc(ni, sizeof(double));
    if (!rate) return -1;
    if (with_rates && (ac_solve_algebraic(s) || (ni && rates(s, rate)))) {
        free(rate);
        return -1;
    }
    ac_values(s, s->t, s->rts);
    if (R) md->scales(s->t, s->z, s->p, s->m, s->scl, s->wf);
    for (int k = 0; k < R; ++k) {
        double g = s->rts[k], v;
        if (fabs(g) > ac_rel_tol(s, k)) v = truth(md, k, g);
        else if (rate[k] != 0.0 && isfinite(rate[k])) v = (rate[k] > 0) == md->upward[k];
        else v = !md->strict[k];
        if (v != s->m[k]) { s->m[k] = v; changed = 1; }
    }
    for (int j = 0; j < md->n_disc; ++j) {
        double u = s->rts[R + j], whole = round(u), v = floor(u);
        if (fabs(u - whole) <= ZERO_RTOL * (fabs(u) + 1.0))
            v = rate[R + j] < 0 ? whole - 1.0 : whole;
        if (v != s->m[R + j]) { s->m[R + j] = v; changed = 1; }
    }
    free(rate);
    if (changed) s->solved = 0;
    return changed;
}

/* Relations (and floor values) the solution clearly contradicts take its side. */
int ac_settle_contradicted(ac_state *s) {
    const ac_model *md = s->md;
    int R = md->n_rel, changed = 0;
    if (ac_solve_algebraic(s)) return -1;
    ac_values(s, s->t, s->rts);
    if (R) md->scales(s->t, s->z, s->p, s->m, s->scl, s->wf);
    for (int k = 0; k < R; ++k) {
        double g = s->rts[k];
        if (fabs(g) > ac_rel_tol(s, k) && truth(md, k, g) != (s->m[k] > 0.5)) {
            s->m[k] = truth(md, k, g);
            changed = 1;
        }
    }
    for (int j = 0; j < md->n_disc; ++j) {
        double u = s->rts[R + j], n = s->m[R + j], tu = ZERO_RTOL * (fabs(u) + 1.0);
        if (u < n - tu || u >= n + 1.0 + tu) { s->m[R + j] = floor(u); changed = 1; }
    }
    if (changed) s->solved = 0;
    return changed;
}
