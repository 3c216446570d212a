/* Discrete-time variables, Boolean and Integer equations and sample() clocks of an
   exported model (runtime/events.py, WhenClauses and discrete_iteration;
   compiler/frontend/sampled.py): the held values held(y) and pre(y) of the discrete
   variables follow the relation and floor items in m, then initial() where the model
   reads it; the when-clauses' code has the conditions (a row per condition, cond_owners
   its clause), the reinit values, the assigned values and, last, start and period of
   each clock.  An assignment marked in assign_eq is the equation of a Boolean or Integer
   variable, evaluated at every event.  The engine (engine.c) calls ac_discrete_iteration
   at an event: Modelica's event iteration (MLS 3.6, sec. 8.6). */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "acausal_fmu.h"

#define DISCRETE_ROUNDS 100

static int items(const ac_model *md) { return md->n_rel + md->n_disc; }

int ac_m_size(const ac_model *md) { return items(md) + 2 * md->n_held + md->has_initial; }

int ac_has_equations(const ac_model *md) {
    for (int a = 0; a < md->n_assign; ++a) if (md->assign_eq[a]) return 1;
    return md->n_pulse > 0;
}

double ac_tick_tol(double t) { return 64 * 2.220446049250313e-16 * fmax(1.0, fabs(t)); }

/* The next tick of clock c: start + k period, a product (no drift over many periods). */
double ac_tick(const ac_state *s, int c) {
    return s->clk[3 * c] + s->clk[3 * c + 2] * s->clk[3 * c + 1];
}

/* Before a run: held and pre values at their start values, initial() true; each clock's
   first tick at or after t0 (start and period are the last rows of the clauses' code). */
int ac_reset_discrete(ac_state *s) {
    const ac_model *md = s->md;
    int held = items(md), row = md->n_when_rows - 2 * md->n_clock;
    for (int j = 0; j < md->n_held; ++j)
        s->m[held + j] = s->m[held + md->n_held + j] = md->held_start[j];
    if (md->has_initial) s->m[ac_m_size(md) - 1] = 1.0;
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

/* A value assigned to held value j: a Boolean's 1 or 0, an Integer's whole number. */
static double typed(const ac_model *md, int j, double v) {
    if (md->held_type[j] == 1) return v > 0.5 ? 1.0 : 0.0;
    if (md->held_type[j] == 2) return nearbyint(v);
    return v;
}

/* The selected assignments (equations, or those of the fired clauses), level by level of
   their data flow: a level reads what the levels before it wrote. */
static int evaluate(ac_state *s, int equations) {
    const ac_model *md = s->md;
    int held = items(md), row = md->n_when + md->n_act, top = -1;
#define SELECTED(a) (equations ? md->assign_eq[a] \
                               : (!md->assign_eq[a] && s->fire[md->assign_owners[a]]))
    for (int a = 0; a < md->n_assign; ++a)
        if (SELECTED(a) && md->assign_levels[a] > top) top = md->assign_levels[a];
    for (int lv = 0; lv <= top; ++lv) {
        s->solved = 0;
        if (lv && ac_solve_algebraic(s)) return -1;
        md->when_rows(s->t, s->z, s->p, s->m, s->wrows, s->ww);
        for (int a = 0; a < md->n_assign; ++a)
            if (SELECTED(a) && md->assign_levels[a] == lv)
                s->m[held + md->assign_slots[a]] = typed(md, md->assign_slots[a],
                                                         s->wrows[row + a]);
    }
#undef SELECTED
    s->solved = 0;
    return top >= 0;
}

/* The assignments of the fired clauses; pre(y) of what they assign is the value before
   the instant while they run, and the new value after it. */
int ac_assign(ac_state *s) {
    const ac_model *md = s->md;
    int held = items(md), pre = held + md->n_held, any = 0;
    for (int a = 0; a < md->n_assign; ++a)
        any |= !md->assign_eq[a] && s->fire[md->assign_owners[a]];
    if (!any) return 0;
    for (int a = 0; a < md->n_assign; ++a)
        if (!md->assign_eq[a]) s->m[pre + md->assign_slots[a]] = s->m[held + md->assign_slots[a]];
    if (evaluate(s, 0) < 0) return -1;
    for (int a = 0; a < md->n_assign; ++a)
        if (!md->assign_eq[a]) s->m[pre + md->assign_slots[a]] = s->m[held + md->assign_slots[a]];
    return 1;
}

/* The equations of the Boolean and Integer variables, with pre() as it is: 1 if a held
   value changed, 0 if not, -1 on failure. */
int ac_update_equations(ac_state *s) {
    const ac_model *md = s->md;
    int held = items(md), changed = 0;
    memcpy(s->held_before, s->m + held, md->n_held * sizeof(double));
    if (evaluate(s, 1) < 0) return -1;
    for (int j = 0; j < md->n_held; ++j) changed |= s->held_before[j] != s->m[held + j];
    return changed;
}

/* Clauses whose condition became true between ``before`` and m, and clocks that tick now,
   fire: reinit actions (values taken before the event), then the assignments.  Returns
   2 if a state was re-initialized, 1 if a clause fired, 0 if none, -1 on failure. */
int ac_fire(ac_state *s, const double *before, int round_) {
    const ac_model *md = s->md;
    int any = 0, moved = 0;
    if (!md->n_clauses) return 0;
    md->when_rows(s->t, s->z, s->p, before, s->wrows_pre, s->ww);
    md->when_rows(s->t, s->z, s->p, s->m, s->wrows, s->ww);
    memset(s->fire, 0, md->n_clauses * sizeof(int));
    for (int c = 0; c < md->n_when; ++c)
        if (s->wrows_pre[c] < 0.5 && s->wrows[c] > 0.5) s->fire[md->cond_owners[c]] = any = 1;
    for (int c = 0; round_ == 0 && c < md->n_clock; ++c)
        if (ac_tick(s, c) <= s->t + ac_tick_tol(s->t)) {
            s->fire[md->clock_owners[c]] = any = 1;
            s->clk[3 * c + 2] += 1.0;
        }
    if (!any) return 0;
    for (int a = 0; a < md->n_act; ++a)
        if (s->fire[md->when_owners[a]]) {
            s->z[md->when_targets[a]] = s->wrows_pre[md->n_when + a];
            moved = 1;
        }
    if (ac_assign(s) < 0) return -1;
    s->solved = 0;
    return moved ? 2 : 1;
}

/* Modelica's event iteration over the equations and the clauses: evaluated with pre() as
   it is, repeated with pre taking the new values until none differs (the relations the
   new values contradict switched in between); a tick's y = sample(...) is false again
   once that holds.  ``initial``: the event that ends the initialization (initial() is
   true in its first round only).  Returns 2 if a state was re-initialized, 1 if a clause
   fired, 0 if none, -1 on failure (a cycle: the message names what keeps changing). */
int ac_discrete_iteration(ac_state *s, const double *before, int initial) {
    const ac_model *md = s->md;
    int N = ac_m_size(md), held = items(md), pre = held + md->n_held, out = 0;
    memcpy(s->m_round, before, N * sizeof(double));
    for (int k = 0; k < DISCRETE_ROUNDS; ++k) {
        if (ac_update_equations(s) < 0) return -1;
        memcpy(s->m_now, s->m, N * sizeof(double));
        int f = ac_fire(s, s->m_round, k);
        if (f < 0) return -1;
        if (f > out) out = f;
        int settled = f == 0;
        for (int j = 0; settled && j < md->n_held; ++j)
            settled = s->m[held + j] == s->m[pre + j];
        if (initial && k == 0) {
            if (md->has_initial) s->m[N - 1] = 0.0;
            settled = 0;            /* the equations read initial() as false from now on */
        }
        if (settled) {
            int pulses = 0;
            for (int j = 0; j < md->n_pulse; ++j) pulses |= s->m[held + md->pulse_slots[j]] != 0.0;
            if (!pulses) return out;
            for (int j = 0; j < md->n_pulse; ++j) s->m[held + md->pulse_slots[j]] = 0.0;
        }
        memcpy(s->m_round, s->m_now, N * sizeof(double));
        memcpy(s->m + pre, s->m + held, md->n_held * sizeof(double));
        s->solved = 0;
        if ((f == 2 ? ac_settle_all(s, 1) : ac_settle_contradicted(s)) < 0) return -1;
    }
    int len = snprintf(s->message, sizeof s->message, "event iteration at t = %.10g: the "
                       "Boolean/Integer equations do not settle after %d rounds, the values "
                       "cycle:", s->t, DISCRETE_ROUNDS);
    for (int j = 0; j < md->n_held && len < (int)sizeof s->message - 80; ++j)
        if (s->m[held + j] != s->m_now[held + j])
            len += snprintf(s->message + len, sizeof s->message - len, " %s",
                            md->held_names[j]);
    return -1;
}
