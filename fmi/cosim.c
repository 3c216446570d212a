/* Co-simulation: the Model Exchange ODE x' = f(t, x) of engine.c integrated inside
   fmi2DoStep.

   Method: the two-stage, L-stable SDIRK method of order 2 (Alexander 1977;
   Hairer & Wanner, Solving ODEs II, sec. IV.6), gamma = 1 - 1/sqrt(2):
       K1 = f(t + gamma h, x + gamma h K1)
       K2 = f(t + h, x + (1 - gamma) h K1 + gamma h K2),   x_new = x + h((1-gamma)K1 + gamma K2)
   with the embedded first-order solution x + h K1; the error estimate
   gamma h (K2 - K1) is filtered by (I - gamma h J)^{-1} (Shampine's device, Hairer &
   Wanner IV.8) so that stiff components do not inflate it.  Each stage is solved by
   simplified Newton with M = I - gamma h J, J = dx'/dx the ODE Jacobian from the
   generated Jacobian of the DAE:  J = D_x - D_A G_A^{-1} G_x.
   Error control: weights rtol |x_i| + rtol nominal_i (acausal's atol = rtol nominal),
   h_new = h min(5, max(0.2, 0.9 err^(-1/2))).  rtol is the tolerance given to
   fmi2SetupExperiment, else the one chosen at export (DefaultExperiment).
   Events: after each accepted step the indicators are evaluated; a crossing is located
   by bisection on the cubic Hermite interpolant of the step (error O(h^4), below the
   step's own), and the event iteration of engine.c runs there.  Time events are landed
   on exactly. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <stdio.h>
#include "acausal_fmu.h"

#define GAMMA 0.29289321881345248
#define NEWTON_STAGE_ITER 8

static void set_x(ac_state *s, double t, const double *x) {
    const ac_model *md = s->md;
    s->t = t;
    for (int i = 0; i < md->n_x; ++i) s->z[md->state_index[i]] = x[i];
    s->solved = 0;
}

static int rhs(ac_state *s, double t, const double *x, double *f) {
    set_x(s, t, x);
    if (ac_derivatives(s)) return -1;
    memcpy(f, s->xdot, s->md->n_x * sizeof(double));
    return 0;
}

/* J = D_x - D_A G_A^{-1} G_x at the current, solved point (row-major n_x x n_x). */
int ac_ode_jacobian(ac_state *s, double *J) {
    const ac_model *md = s->md;
    int nx = md->n_x, na = md->n_alg, nsz = md->n_state_z;
    double *GA = (double *)calloc((size_t)na * na + (size_t)na * nx + (size_t)nx * na + 1,
                                  sizeof(double));
    double *S = GA + (size_t)na * na, *DA = S + (size_t)na * nx;
    int *piv = (int *)calloc(na + 1, sizeof(int));
    if (!GA || !piv) { free(GA); free(piv); return -1; }
    memset(J, 0, (size_t)nx * nx * sizeof(double));
    md->jacobian(s->t, s->z, s->p, s->m, s->jac, s->wf);
    for (int e = 0; e < md->n_jac; ++e) {
        int r = md->jac_rows[e], c = md->jac_cols[e];
        int a = s->algpos[c], x = s->statepos[c];
        double v = s->jac[e];
        if (r < md->n_res) {
            if (a >= 0) GA[r * na + a] += v;
            else if (x >= 0) S[r * nx + x] += v;
        } else {
            int i = r - md->n_res;
            if (a >= 0) DA[i * na + a] += v;
            else if (x >= 0) J[i * nx + x] += v;
        }
    }
    for (int i = nsz; i < nx; ++i) {        /* linked states: x_i' = z[link_d] */
        int d = md->link_d[i - nsz];
        if (s->algpos[d] >= 0) DA[i * na + s->algpos[d]] = 1.0;
        else if (s->statepos[d] >= 0) J[i * nx + s->statepos[d]] = 1.0;
    }
    int status = 0;
    if (na) {
        if (ac_lu(GA, na, piv)) { status = -1; goto done; }
        double *col = (double *)malloc(sizeof(double) * na);
        for (int j = 0; j < nx; ++j) {
            for (int i = 0; i < na; ++i) col[i] = S[i * nx + j];
            ac_lu_solve(GA, na, piv, col);
            for (int i = 0; i < nx; ++i) {
                double acc = 0.0;
                for (int k = 0; k < na; ++k) acc += DA[i * na + k] * col[k];
                J[i * nx + j] -= acc;
            }
        }
        free(col);
    }
done:
    free(GA);
    free(piv);
    return status;
}

static double wnorm(const double *v, const double *w, int n) {
    double a = 0.0;
    for (int i = 0; i < n; ++i) a += (v[i] / w[i]) * (v[i] / w[i]);
    return n ? sqrt(a / n) : 0.0;
}

/* Y = base + gamma h f(tc, Y) by simplified Newton with the factored M; Y holds the guess. */
static int stage(ac_state *s, double tc, double gh, const double *base, double *Y, double *K,
                 const double *M, const int *piv, const double *w, double *tmp) {
    int n = s->md->n_x;
    for (int it = 0; it < NEWTON_STAGE_ITER; ++it) {
        if (rhs(s, tc, Y, K)) return -1;
        for (int i = 0; i < n; ++i) tmp[i] = -(Y[i] - base[i] - gh * K[i]);
        ac_lu_solve(M, n, piv, tmp);
        for (int i = 0; i < n; ++i) Y[i] += tmp[i];
        double dn = wnorm(tmp, w, n);
        if (!isfinite(dn)) return -1;
        if (dn <= 1e-3) return rhs(s, tc, Y, K);
    }
    return -1;
}

static void hermite(double t0, const double *x0, const double *f0, double t1,
                    const double *x1, const double *f1, double t, double *x, int n) {
    double h = t1 - t0, u = (t - t0) / h;
    double h00 = (1 + 2 * u) * (1 - u) * (1 - u), h10 = u * (1 - u) * (1 - u);
    double h01 = u * u * (3 - 2 * u), h11 = u * u * (u - 1);
    for (int i = 0; i < n; ++i) x[i] = h00 * x0[i] + h10 * h * f0[i] + h01 * x1[i] + h11 * h * f1[i];
}

/* 1 if an indicator that was >= 0 at the step's start (r0) is negative now. */
static int crossed(ac_state *s, double *r, const double *r0, int nr) {
    if (ac_oriented(s, r)) return -1;
    for (int k = 0; k < nr; ++k) if (r[k] < 0 && r0[k] >= 0) return 1;
    return 0;
}

int ac_do_step(ac_state *s, double t_end) {
    const ac_model *md = s->md;
    int n = md->n_x, nr = md->n_rel + 2 * md->n_disc, status = -1;
    double *J = s->cs_buf, *M = J + (size_t)n * n, *x0 = M + (size_t)n * n;
    double *f0 = x0 + n, *Y1 = f0 + n, *K1 = Y1 + n, *Y2 = K1 + n, *K2 = Y2 + n;
    double *e = K2 + n, *w = e + n, *tmp = w + n, *base = tmp + n, *xe = base + n;
    int *piv = (int *)calloc(n + 1, sizeof(int));
    double *r = (double *)calloc(2 * nr + 1, sizeof(double)), *r0 = r + nr;
    if (!piv || !r) goto out;
    if (nr) {
        /* inputs or parameters set since the last step may contradict the discrete
           state: an event at the communication point, as an importer's event mode */
        int c0, changed;
        if (ac_oriented(s, r0)) goto out;
        for (c0 = 0; c0 < nr && r0[c0] >= 0; ++c0) {}
        if (c0 < nr) {
            s->events++;
            if (ac_event(s, &changed)) goto out;
        }
    }
    while (s->t < t_end) {
        double t = s->t;
        if (s->has_next_time && s->next_time <= t + ac_tick_tol(t)) {
            /* a time event within round-off of the communication point (a clock's
               tick start + k period computed a bit past it): taken here */
            int changed;
            s->events++;
            if (ac_event(s, &changed)) goto out;
            continue;
        }
        for (int i = 0; i < n; ++i) x0[i] = s->z[md->state_index[i]];
        if (rhs(s, t, x0, f0) || ac_ode_jacobian(s, J)) goto out;
        if (nr && ac_oriented(s, r0)) goto out;
        for (int i = 0; i < n; ++i)
            w[i] = s->rtol * fabs(x0[i]) + s->rtol * md->nominal[md->state_index[i]];
        if (s->h_int <= 0.0) {
            double d0 = wnorm(x0, w, n), d1 = wnorm(f0, w, n);
            s->h_int = (d0 > 1e-5 && d1 > 1e-5) ? 0.01 * d0 / d1 : 1e-6;
        }
        double h = fmin(s->h_int, t_end - t);
        int timed = 0;
        if (s->has_next_time && s->next_time <= t + h) { h = s->next_time - t; timed = 1; }
        if (t_end - (t + h) <= 1e-12 * fmax(1.0, fabs(t_end))) h = t_end - t;
        if (!(h > 1e-14 * fmax(1.0, fabs(t)))) {
            snprintf(s->message, sizeof s->message,
                     "the integrator's step fell below round-off at t = %.10g", t);
            goto out;
        }
        double gh = GAMMA * h, err = INFINITY;
        for (int i = 0; i < n * n; ++i) M[i] = -gh * J[i];
        for (int i = 0; i < n; ++i) M[i * n + i] += 1.0;
        int ok = n == 0 || ac_lu(M, n, piv) == 0;
        if (ok) {
            for (int i = 0; i < n; ++i) Y1[i] = x0[i] + gh * f0[i];
            ok = stage(s, t + gh, gh, x0, Y1, K1, M, piv, w, tmp) == 0;
        }
        if (ok) {
            for (int i = 0; i < n; ++i) {
                base[i] = x0[i] + (1.0 - GAMMA) * h * K1[i];
                Y2[i] = base[i] + gh * K1[i];
            }
            ok = stage(s, t + h, gh, base, Y2, K2, M, piv, w, tmp) == 0;
        }
        if (ok) {
            for (int i = 0; i < n; ++i) {
                e[i] = gh * (K2[i] - K1[i]);
                w[i] = s->rtol * fmax(fabs(x0[i]), fabs(Y2[i]))
                     + s->rtol * md->nominal[md->state_index[i]];
            }
            ac_lu_solve(M, n, piv, e);
            err = wnorm(e, w, n);
        }
        if (!ok || !(err <= 1.0)) {
            s->rejected++;
            s->h_int = ok ? h * fmax(0.2, 0.9 / sqrt(err)) : 0.25 * h;
            set_x(s, t, x0);
            continue;
        }
        s->steps++;
        s->h_int = h * fmin(5.0, fmax(0.2, 0.9 / sqrt(fmax(err, 1e-10))));
        /* K2 = f(t + h, Y2): the end point's derivative, for the interpolant */
        set_x(s, t + h, Y2);
        int c = nr ? crossed(s, r, r0, nr) : 0;
        if (c < 0) goto out;
        if (c) {
            double ta = t, tb = t + h;
            for (int it = 0; it < 80 && tb - ta > 1e-13 * fmax(1.0, fabs(tb)); ++it) {
                double tm = 0.5 * (ta + tb);
                hermite(t, x0, f0, t + h, Y2, K2, tm, xe, n);
                set_x(s, tm, xe);
                int cm = crossed(s, r, r0, nr);
                if (cm < 0) goto out;
                if (cm) tb = tm; else ta = tm;
            }
            hermite(t, x0, f0, t + h, Y2, K2, tb, xe, n);
            set_x(s, tb, xe);
            timed = 1;
        }
        if (timed || (s->has_next_time && s->t >= s->next_time)) {
            int changed;
            s->events++;
            if (ac_event(s, &changed)) goto out;
        } else {
            ac_release(s);
        }
    }
    status = 0;
out:
    free(piv);
    free(r);
    return status;
}
