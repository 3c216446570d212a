/* The data of one exported model, written by acausal.fmi.export into model.c, and the
   engine that runs it (engine.c) behind the FMI 2.0 functions (fmu.c).

   Notation (acausal's README, "The system the solver sees"): z is the solver vector of
   the compiled model; its states x = z[state_index] (the causal form's states first,
   then the linked states of the full form); the other entries of z (tearing variables,
   or every non-state variable of the full form) are the algebraic unknowns z[alg],
   solved from G(t, z) = 0 inside the FMU.  The generated functions have the contract
       int f(double t, const double *y, const double *p, const double *m,
             double *out, double *w)
   and return how many outputs are not finite. */
#ifndef ACAUSAL_FMU_H
#define ACAUSAL_FMU_H

#include <stddef.h>

typedef int (*ac_fn)(double, const double *, const double *, const double *, double *,
                     double *);

/* where a variable's value comes from: a parameter (settable), expand()[index] times
   sign, a constant, a state derivative, or sign p[index] + value (not settable) */
enum { AC_PARAM = 0, AC_EXPAND = 1, AC_CONST = 2, AC_DERIV = 3, AC_PAFFINE = 4 };

typedef struct {
    const char *guid;
    int n_z, n_x, n_res, n_rows, n_state_z, n_alg;
    const int *state_index, *alg_index, *link_d;
    const double *nominal, *start;
    int n_p;
    const double *p_start;
    int n_rel, n_disc;                       /* relations, then frozen floor values */
    const int *upward, *strict, *timed;      /* per relation; timed per item */
    const double *rel_nominal;
    int n_jac;
    const int *jac_rows, *jac_cols;
    ac_fn residual, jacobian, roots, scales, expand;
    int work_f, n_all;
    int n_init_rows, n_init, n_ijac;         /* rows of i_residual, kept rows, entries */
    const int *init_keep, *ijac_rows, *ijac_cols;
    ac_fn init_residual, init_jacobian;
    int work_i;
    int n_start;                             /* kept initial rows  z[k] = start value */
    const int *start_row, *start_z;          /* (position among the kept rows, k) */
    const double *start_value;
    int n_when, n_act;                       /* when-clauses and their reinit actions */
    const int *when_targets, *when_owners;
    ac_fn when_rows;
    int work_w;
    int n_when_rows;                         /* conditions, reinits, assigned values, clocks */
    int n_held;                              /* discrete variables: held(y), pre(y) in m */
    const double *held_start;
    int n_assign;                            /* assignments: held slot, clause, data flow */
    const int *assign_slots, *assign_owners, *assign_levels;
    int n_clock;                             /* sample() clocks: the clause of each */
    const int *clock_owners;
    int n_clauses;                           /* when-clauses; n_when counts their conditions */
    const int *cond_owners;                  /* the clause of each condition row */
    const int *assign_eq;                    /* 1: the assignment is the equation of a
                                                Boolean or Integer, evaluated at every event */
    const int *held_type;                    /* per held value: 0 Real, 1 Boolean, 2 Integer */
    const char *const *held_names;
    int n_pulse;                             /* held values y = sample(...): false again */
    const int *pulse_slots;                  /* once the instant is over */
    int has_initial;                         /* initial() is read: m's last entry */
    int n_vars;                              /* the FMI variables: Real ones first (their
                                                value reference is their index), then the
                                                Boolean ones, then the Integer ones */
    int n_real_vars, n_bool_vars;
    const int *var_kind, *var_index, *var_start;   /* var_start: start row or -1 */
    const double *var_sign, *var_value;
    double default_rtol;
} ac_model;

extern const ac_model AC_MODEL;

typedef struct {
    const ac_model *md;
    double t;
    double *z, *p, *m, *m_pre, *xdot, *all;
    double *wf, *wi, *ww, *rows, *jac, *rts, *scl, *ijac, *irows, *wrows, *wrows_pre;
    double *x_start;                         /* the start values the importer set */
    double *dense, *rhs, *zsave;             /* Newton: dense matrix (n_z x n_z), rhs */
    double *offset;                          /* raised indicators of items armed at zero */
    int *piv, *statepos, *algpos, *initpos;             /* z index -> column; kept row -> row */
    int solved, expanded, failed;
    int has_next_time;
    double next_time;
    double *m_round, *clk;                   /* m after a round of firing; clocks' start,
                                                period and next tick */
    double *m_now, *m_settle;                /* m before a round's assignments, before a
                                                settling of contradicted relations */
    double *held_before;                     /* the held values before the equations ran */
    int *fire;                               /* per clause */
    int initial_event;                       /* the event that ends the initialization */
    char message[512];
    /* co-simulation */
    double rtol, h_int;
    double *cs_buf;                          /* work of the integrator */
    long steps, rejected, events;
} ac_state;

#define ZERO_RTOL 1e-10                     /* a relation's zero tolerance, relative */

int ac_alloc(ac_state *s, const ac_model *md);
void ac_free(ac_state *s);
int ac_initialize(ac_state *s);
int ac_event(ac_state *s, int *states_changed);
void ac_next_time_event(ac_state *s);
int ac_expand(ac_state *s);
int ac_ode_jacobian(ac_state *s, double *J);
void ac_arm(ac_state *s);
void ac_release(ac_state *s);
int ac_do_step(ac_state *s, double t_end);
int ac_reset_discrete(ac_state *s);          /* discrete.c */
int ac_assign(ac_state *s);
int ac_m_size(const ac_model *md);
int ac_has_equations(const ac_model *md);
int ac_update_equations(ac_state *s);
int ac_fire(ac_state *s, const double *before, int round_);
int ac_discrete_iteration(ac_state *s, const double *before, int initial);
double ac_tick(const ac_state *s, int c);
double ac_tick_tol(double t);

/* modes.c: Newton on a square system, the algebraic unknowns, the relations */
typedef struct {
    int n;                 /* unknowns */
    const int *cols;       /* z index of each unknown */
    int initial;           /* 1: rows [G; kept initial rows] over all z */
} ac_system;

void *ac_zalloc(int n, size_t size);        /* calloc of at least one element */
int ac_lu(double *A, int n, int *piv);
void ac_lu_solve(const double *A, int n, const int *piv, double *b);
int ac_newton(ac_state *s, const ac_system *sys);
int ac_solve_algebraic(ac_state *s);
int ac_derivatives(ac_state *s);
int ac_items(const ac_model *md);
void ac_values(ac_state *s, double t, double *v);
double ac_rel_tol(ac_state *s, int k);
int ac_oriented(ac_state *s, double *r);
int ac_settle_all(ac_state *s, int with_rates);
int ac_settle_contradicted(ac_state *s);

#endif
