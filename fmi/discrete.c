/* Discrete-time variables and sample() clocks of an exported model (runtime/events.py,
   WhenClauses; compiler/frontend/sampled.py): the held values held(y) and pre(y) of the discrete
   variables follow the relation and floor items in m; the when-clauses' code has the
   conditions, the reinit values, the assigned values and, last, start and period of
   each clock.  The engine (engine.c) fires clocks at their ticks and calls ac_assign
   for the clauses that fired. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "acausal_fmu.h"

static int items(const ac_model *md) { return md->n_rel + md->n_disc; }

double ac_tick_tol(double t) { return 64 * 2.220446049250313e-16 * fmax(1.0, fabs(t)); }

/* The next tick of clock c: start + k period, a product (no drift over many periods). */
double ac_tick(const ac_state *s, int c) {
    return s->clk[3 * c] + s->clk[3 * c + 2] * s->clk[3 * c + 1];
}

/* Before a run: held and pre values at their start values; each clock's first tick at or
   after t0 (start and period are the last rows of the when-clauses' code). */
int ac_reset_discrete(ac_state *s) {
    const ac_model *md = s->md;
    int held = items(md), row = md->n_when_rows - 2 * md->n_clock;
    for (int j = 0; j < md->n_held; ++j)
        s->m[held + j] = s->m[held + md->n_held + j] = md->held_start[j];
    if (md->n_clock) md->when_rows(s->t, s->z, s->p, s->m, s->wrows, s->ww);
    for (int c = 0; c < md->n_clock; ++c) {
        double t0 = s->wrows[row + 2 * c], T = s->wrows[row + 2 * c + 1];
        if (!(isfinite(t0) && isfinite(T) && T > 0)) {
            snprintf(s->message, sizeof s->message, "sample(start = %g, period = %g) needs "
                     "a finite start and a positive period", t0, T);
            return -1;
        }
        double k = fmax(ceil((s->t - t0) / T), 0.0);
        if (k > 0 && t0 + (k - 1) * T >= s->t - ac_tick_tol(s->t)) k -= 1;
        s->clk[3 * c] = t0; s->clk[3 * c + 1] = T; s->clk[3 * c + 2] = k;
    }
    return 0;
}

/* The assignments of the fired clauses, level by level of their data flow (a level reads
   what the levels before it assigned); pre(y) is the value before the instant while they
   run, and the new value after it. */
int ac_assign(ac_state *s) {
    const ac_model *md = s->md;
    int held = items(md), pre = held + md->n_held, row = md->n_when + md->n_act, top = -1;
    for (int a = 0; a < md->n_assign; ++a)
        if (s->fire[md->assign_owners[a]] && md->assign_levels[a] > top)
            top = md->assign_levels[a];
    if (top < 0) return 0;
    memcpy(s->m + pre, s->m + held, md->n_held * sizeof(double));
    for (int lv = 0; lv <= top; ++lv) {
        s->solved = 0;
        if (lv && ac_solve_algebraic(s)) return -1;
        md->when_rows(s->t, s->z, s->p, s->m, s->wrows, s->ww);
        for (int a = 0; a < md->n_assign; ++a)
            if (s->fire[md->assign_owners[a]] && md->assign_levels[a] == lv)
                s->m[held + md->assign_slots[a]] = s->wrows[row + a];
    }
    memcpy(s->m + pre, s->m + held, md->n_held * sizeof(double));
    s->solved = 0;
    return 1;
}
