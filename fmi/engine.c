/* The engine of an exported model: the outputs, the next time event, the event
   iteration and the initial system, over the algebraic solve, the state derivatives and
   the relations' modes of modes.c.

   It follows acausal's runtime (runtime/events.py, runtime/initial.py):
   * At an event: items whose indicator is negative switch; time-linear items at zero
     take the side of their exact slope; fired when-clauses re-initialize states (with
     the values before the event, Modelica's pre) and assign discrete variables (held
     values in m, in data-flow order, runtime/events.py; discrete.c); sample() clocks
     fire at start + k period; then the algebraic unknowns are solved again and
     contradicted relations set until nothing changes (MLS 3.6, sec. 8.6).
   * The initial system: Newton over all z on [G; kept initial rows]. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <stdio.h>
#include "acausal_fmu.h"

#define MODE_ROUNDS 20


int ac_alloc(ac_state *s, const ac_model *md) {
    int n_items = md->n_rel + md->n_disc, n = md->n_z, n_m = ac_m_size(md);
    memset(s, 0, sizeof(*s));
    s->md = md;
    s->z = ac_zalloc(n, sizeof(double));
    s->zsave = ac_zalloc(n, sizeof(double));
    s->p = ac_zalloc(md->n_p, sizeof(double));
    s->m = ac_zalloc(n_m, sizeof(double));
    s->m_pre = ac_zalloc(n_m, sizeof(double));
    s->m_round = ac_zalloc(n_m, sizeof(double));
    s->m_now = ac_zalloc(n_m, sizeof(double));
    s->m_settle = ac_zalloc(n_m, sizeof(double));
    s->held_before = ac_zalloc(md->n_held, sizeof(double));
    s->clk = ac_zalloc(3 * md->n_clock, sizeof(double));
    s->fire = ac_zalloc(md->n_clauses, sizeof(int));
    s->xdot = ac_zalloc(md->n_x, sizeof(double));
    s->all = ac_zalloc(md->n_all, sizeof(double));
    s->wf = ac_zalloc(md->work_f, sizeof(double));
    s->wi = ac_zalloc(md->work_i, sizeof(double));
    s->ww = ac_zalloc(md->work_w, sizeof(double));
    s->rows = ac_zalloc(md->n_rows, sizeof(double));
    s->jac = ac_zalloc(md->n_jac, sizeof(double));
    s->rts = ac_zalloc(n_items, sizeof(double));
    s->scl = ac_zalloc(md->n_rel, sizeof(double));
    s->ijac = ac_zalloc(md->n_ijac, sizeof(double));
    s->irows = ac_zalloc(md->n_init_rows, sizeof(double));
    s->wrows = ac_zalloc(md->n_when_rows, sizeof(double));
    s->wrows_pre = ac_zalloc(md->n_when_rows, sizeof(double));
    s->x_start = ac_zalloc(md->n_start, sizeof(double));
    if (md->n_start) memcpy(s->x_start, md->start_value, md->n_start * sizeof(double));
    s->dense = ac_zalloc(n * n, sizeof(double));
    s->rhs = ac_zalloc(n, sizeof(double));
    s->piv = ac_zalloc(n, sizeof(int));
    s->algpos = ac_zalloc(n, sizeof(int));
    s->statepos = ac_zalloc(n, sizeof(int));
    s->offset = ac_zalloc(md->n_rel + 2 * md->n_disc, sizeof(double));
    s->initpos = ac_zalloc(md->n_init_rows, sizeof(int));
    s->cs_buf = ac_zalloc(12 * md->n_x + 2 * md->n_x * md->n_x, sizeof(double));
    if (!s->z || !s->dense || !s->cs_buf) return -1;
    for (int i = 0; i < n; ++i) s->algpos[i] = -1;
    for (int i = 0; i < md->n_alg; ++i) s->algpos[md->alg_index[i]] = i;
    for (int i = 0; i < n; ++i) s->statepos[i] = -1;
    for (int i = 0; i < md->n_x; ++i) s->statepos[md->state_index[i]] = i;
    for (int i = 0; i < md->n_init_rows; ++i) s->initpos[i] = -1;
    for (int i = 0; i < md->n_init; ++i) s->initpos[md->init_keep[i]] = md->n_res + i;
    memcpy(s->z, md->start, n * sizeof(double));
    memcpy(s->p, md->p_start, md->n_p * sizeof(double));
    s->rtol = md->default_rtol;
    return 0;
}

void ac_free(ac_state *s) {
    double *bufs[] = {s->m_round, s->m_now, s->m_settle, s->held_before, s->clk, s->z, s->zsave, s->p, s->m, s->m_pre, s->xdot, s->all, s->wf, s->wi,
                      s->ww, s->rows, s->jac, s->rts, s->scl, s->ijac, s->irows, s->wrows,
                      s->wrows_pre, s->dense, s->rhs, s->cs_buf, s->offset, s->x_start};
    for (size_t k = 0; k < sizeof(bufs) / sizeof(bufs[0]); ++k) free(bufs[k]);
    free(s->piv); free(s->algpos); free(s->statepos); free(s->initpos); free(s->fire);
}

int ac_expand(ac_state *s) {
    if (ac_solve_algebraic(s)) return -1;
    if (!s->expanded && s->md->n_all) s->md->expand(s->t, s->z, s->p, s->m, s->all, s->wf);
    s->expanded = 1;
    return 0;
}

/* Values at t and at t + 1 with z held: exact slopes of the time-linear items. */
static void slopes(ac_state *s, double *v0, double *slope) {
    int ni = ac_items(s->md);
    ac_values(s, s->t, v0);
    ac_values(s, s->t + 1.0, slope);
    for (int k = 0; k < ni; ++k) slope[k] -= v0[k];
}

void ac_next_time_event(ac_state *s) {
    const ac_model *md = s->md;
    int R = md->n_rel, ni = ac_items(md);
    double *v0 = (double *)ac_zalloc(2 * ni, sizeof(double)), *sl = v0 + ni;
    double t_min = s->t + 64 * 2.220446049250313e-16 * fmax(1.0, fabs(s->t));
    s->has_next_time = 0;
    if (!v0) return;
    for (int c = 0; c < md->n_clock; ++c) {
        double te = ac_tick(s, c);
        if (te > t_min && (!s->has_next_time || te < s->next_time)) {
            s->next_time = te;
            s->has_next_time = 1;
        }
    }
    slopes(s, v0, sl);
    for (int k = 0; k < ni; ++k) {
        if (!md->timed[k] || sl[k] == 0.0 || !isfinite(sl[k])) continue;
        double target = 0.0;
        if (k >= R) target = sl[k] > 0 ? s->m[k] + 1.0 : s->m[k];
        double te = s->t + (target - v0[k]) / sl[k];
        if (te > t_min && (!s->has_next_time || te < s->next_time)) {
            s->next_time = te;
            s->has_next_time = 1;
        }
    }
    free(v0);
}

/* -- initialization (runtime/initial.py) ------------------------------------------------- */
int ac_initialize(ac_state *s) {
    const ac_model *md = s->md;
    int *cols = (int *)ac_zalloc(md->n_z, sizeof(int));
    ac_system sys = {md->n_z, cols, 1};
    if (!cols) return -1;
    for (int i = 0; i < md->n_z; ++i) cols[i] = i;
    s->solved = 0;
    if (ac_reset_discrete(s)) { free(cols); return -1; }
    ac_settle_all(s, 0);
    for (int round_ = 0; round_ < 10; ++round_) {
        if (md->n_z && ac_newton(s, &sys)) {
            snprintf(s->message, sizeof s->message,
                     "initialization at t = %.10g: Newton's method on the initial equations "
                     "failed", s->t);
            free(cols);
            return -1;
        }
        s->solved = 0;
        int changed = ac_settle_all(s, 1);
        if (changed < 0) break;
        if (changed == 0 && ac_has_equations(md))      /* pre() at the start values */
            changed = ac_update_equations(s);
        if (changed < 0) break;
        if (!changed) {
            free(cols);
            ac_next_time_event(s);
            if (ac_derivatives(s)) return -1;
            ac_arm(s);
            /* the event that ends the initialization: the equations iterate with pre()
               taking their values, clauses made true by initial() and ticks at t0 fire */
            int ends = ac_has_equations(md) || md->has_initial, due = 0;
            for (int c = 0; c < md->n_clock; ++c)
                due |= ac_tick(s, c) <= s->t + ac_tick_tol(s->t);
            if (!ends && !due) return 0;
            s->initial_event = ends;
            int status = ac_event(s, &round_);
            s->initial_event = 0;
            if (md->has_initial) s->m[ac_m_size(md) - 1] = 0.0;
            return status;
        }
    }
    snprintf(s->message, sizeof s->message,
             "initialization at t = %.10g: the relations do not settle", s->t);
    free(cols);
    return -1;
}

/* -- event iteration (runtime/events.py) ------------------------------------------------- */
int ac_event(ac_state *s, int *states_changed) {
    const ac_model *md = s->md;
    int R = md->n_rel, ni = ac_items(md), nr = md->n_rel + 2 * md->n_disc, fired = 0;
    double *r = (double *)ac_zalloc(nr + 2 * ni, sizeof(double)), *v0 = r + nr, *sl = v0 + ni;
    *states_changed = 0;
    if (!r) return -1;
    int N = ac_m_size(md), equations = ac_has_equations(md) || s->initial_event;
    memcpy(s->m_pre, s->m, N * sizeof(double));
    if (s->initial_event && md->has_initial) s->m_pre[N - 1] = 0.0;   /* false before */
    if (ni) {
        ac_release(s);
        if (ac_oriented(s, r)) goto fail;
        for (int k = 0; k < R; ++k) if (r[k] < 0) s->m[k] = 1.0 - s->m[k];
        for (int j = 0; j < md->n_disc; ++j) {
            double u = s->rts[R + j], n = s->m[R + j];
            if (r[R + 2 * j] < 0) s->m[R + j] = fmin(floor(u), n - 1.0);
            if (r[R + 2 * j + 1] < 0) s->m[R + j] = fmax(floor(u), n + 1.0);
        }
        /* time-linear items at their switching time: the side of their exact slope */
        slopes(s, v0, sl);
        for (int k = 0; k < ni; ++k) {
            if (!md->timed[k] || sl[k] == 0.0 || !isfinite(sl[k])) continue;
            if (k < R) {
                if (fabs(v0[k]) <= 4.0 * ac_rel_tol(s, k)) s->m[k] = (sl[k] > 0) == md->upward[k];
            } else {
                double whole = round(v0[k]);
                if (fabs(v0[k] - whole) <= 4.0 * ZERO_RTOL * (fabs(v0[k]) + 1.0))
                    s->m[k] = sl[k] < 0 ? whole - 1.0 : whole;
            }
        }
        s->solved = 0;
    }
    if (equations) {
        int f = ac_discrete_iteration(s, s->m_pre, s->initial_event);
        if (f < 0) goto fail;
        fired = f == 2;
    } else {
        /* with discrete variables, an assignment can make another clause's condition
           true at the same instant: it fires in the next round */
        memcpy(s->m_round, s->m_pre, N * sizeof(double));
        for (int round_ = 0; md->n_when + md->n_clock && round_ < (md->n_held ? MODE_ROUNDS : 1);
             ++round_) {
            memcpy(s->m_now, s->m, N * sizeof(double));
            int f = ac_fire(s, s->m_round, round_);
            if (f < 0) goto fail;
            if (!f) break;
            fired |= f == 2;
            memcpy(s->m_round, s->m_now, N * sizeof(double));
            if (ac_settle_all(s, 1) < 0) goto fail;
        }
    }
    for (int round_ = 0; ; ++round_) {
        memcpy(s->m_settle, s->m, N * sizeof(double));
        int changed = ac_settle_contradicted(s);
        if (changed < 0) goto fail;
        if (!changed) break;
        if (equations) {          /* what reads the relations that switched */
            int f = ac_discrete_iteration(s, s->m_settle, 0);
            if (f < 0) goto fail;
            fired |= f == 2;
        }
        if (round_ == MODE_ROUNDS) {
            snprintf(s->message, sizeof s->message,
                     "event iteration at t = %.10g did not settle", s->t);
            goto fail;
        }
    }
    free(r);
    *states_changed = fired;
    ac_next_time_event(s);
    if (ac_derivatives(s)) return -1;
    ac_arm(s);
    return 0;
fail:
    free(r);
    return -1;
}
