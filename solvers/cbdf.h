/* The state of the compiled BDF step loop (cbdf.c): one struct, shared with Python.

   Python (acausal.solvers.cbdf) owns every buffer and reads this declaration itself
   (acausal.solvers.cbdf_layout parses the struct below into a ctypes.Structure), so the
   two views have one source; tests/solvers/test_cbdf_layout.py compiles offsetof() of
   every field and compares.  Integers are int64_t and pointers are pointers on every
   platform (LP64 and LLP64 alike); nothing here is a C `long`.

   One field a line, `type name;` or `type name[N];`, then its comment: the parser reads
   that form and nothing else between the struct's braces.  Names borrowed from IDA
   (Hindmarsh et al. 2005, the DASSL/IDA Fortran names): hh the step to try, hused the
   last step taken, kk the order to try, kused the last order used, ns the number of
   steps at constant step size and order, cj the leading coefficient alpha_s/h,
   cjold the cj of the last iteration matrix, ss the Newton convergence rate estimate,
   phi the modified divided differences, psi/alpha/beta/sigma/gamma the BDF's
   variable-step coefficients. */
#ifndef ACAUSAL_CBDF_H
#define ACAUSAL_CBDF_H

#include <stdint.h>

#if defined(_WIN32)
#define CBDF_API __declspec(dllexport)
#else
#define CBDF_API
#endif

#define CBDF_NCOEF 7               /* MAXORD + 2 coefficients of each kind */
#define CBDF_NORDERS 8             /* steps counted per order 0..7 */

typedef struct cbdf_state {
  /* -- the integration: read and written by the loop ---------------------------------- */
  double tn;                       /* time of the last accepted step */
  double t_prev;                   /* time of the step before it */
  double t_stop;                   /* a step lands exactly here (inf: none) */
  double hh;                       /* the step size to try next */
  double hused;                    /* the step size of the last accepted step */
  double cj;                       /* alpha_s / h, the leading coefficient */
  double cjold;                    /* cj of the current iteration matrix */
  double cjlast;                   /* cj of the previous step */
  double cjratio;                  /* cj / cjold */
  double ss;                       /* Newton's convergence rate estimate */
  double rtol;                     /* relative tolerance */
  double max_step;                 /* the largest step allowed */
  double psi[CBDF_NCOEF];          /* psi_i: sums of the last step sizes */
  double alpha[CBDF_NCOEF];        /* alpha_i = h / psi_i */
  double beta[CBDF_NCOEF];         /* beta_i: phi's scaling for a new step size */
  double sigma[CBDF_NCOEF];        /* sigma_i: error constants */
  double gamma[CBDF_NCOEF];        /* gamma_i: the predictor's derivative weights */
  double alphas[CBDF_NCOEF];       /* alpha_s of each order (-sum of 1/j) */
  int64_t n;                       /* unknowns */
  int64_t kk;                      /* order to try next */
  int64_t kused;                   /* order of the last accepted step */
  int64_t phase;                   /* 0 while the order still rises freely, then 1 */
  int64_t ns;                      /* steps at the current step size and order */
  int64_t nst;                     /* steps since the last restart */
  int64_t force_setup;             /* 1: form a new iteration matrix at the next step */
  int64_t kmax;                    /* the highest order allowed now */
  int64_t max_order;               /* the highest order allowed in this run */
  int64_t crawl;                   /* failed attempts on algebraic unknowns alone in a row */
  int64_t max_crawl;               /* that many end the step with F_CRAWL (bdf.py) */
  /* -- a run of the loop: set by Python before cbdf_run -------------------------------- */
  int64_t mode;                    /* 0: a compiled model's functions, 1: callbacks */
  int64_t budget;                  /* steps allowed before returning */
  int64_t n_roots;                 /* zero-crossing functions watched (0: none) */
  int64_t all_steps;               /* 1: output every step, 0: the times of t_eval */
  int64_t n_eval;                  /* length of t_eval */
  int64_t i_eval;                  /* next index into t_eval (written back) */
  int64_t capacity;                /* output points the buffers hold */
  int64_t any_algebraic;           /* 1: some rows have no derivative */
  int64_t any_self_scaled;         /* 1: some unknowns are self-scaled (no weight) */
  int64_t sparse;                  /* 1: the sparse LU (cbdf_sparse.c), 0: dense */
  /* -- what the run did: written by the loop ------------------------------------------- */
  int64_t count;                   /* output points written */
  int64_t pending;                 /* 1: the last step's output did not fit */
  int64_t fail_kind;               /* why a failed run stopped (F_... of cbdf.c) */
  int64_t has_fail;                /* 1: weighted holds the failed correction */
  int64_t has_last;                /* 1: last_err holds the last step's error */
  int64_t equilibrated;            /* 1: the dense LU factors the equilibrated matrix */
  double fail_t;                   /* time of the failed step's start */
  double fail_h;                   /* its step size */
  double fail_cj;                  /* cj of a singular iteration matrix */
  double fail_tj;                  /* the time it was formed at */
  int64_t n_residuals;             /* residual evaluations */
  int64_t n_jacobians;             /* Jacobian evaluations */
  int64_t n_lu;                    /* LU factorizations */
  int64_t n_newton;                /* Newton iterations */
  int64_t n_error_fails;           /* error-test failures */
  int64_t n_newton_fails;          /* Newton (convergence) failures */
  int64_t n_steps;                 /* steps accepted */
  int64_t orders[CBDF_NORDERS];    /* steps accepted at each order */
  /* -- buffers owned by Python --------------------------------------------------------- */
  double *phi;                     /* (max_order + 2) x n divided differences */
  const double *atol;              /* n absolute tolerances */
  const double *ss_mask;           /* n: 0 for a self-scaled unknown, else 1 */
  const double *err_mask;          /* n: 0 for an unknown left out of the error test */
  const double *alg_mask;          /* n: 1 for an algebraic unknown, else 0 */
  double *scratch;                 /* dense n x n (not with the sparse LU) + 13 n */
  double *lu;                      /* n x n: the dense LU */
  int64_t *piv;                    /* n: the dense LU's pivot rows */
  const double *t_eval;            /* n_eval requested output times */
  double *out_t;                   /* capacity output times */
  double *out_y;                   /* capacity x n */
  double *out_yp;                  /* capacity x n */
  double *weighted;                /* n: the last failed correction, weighted */
  double *last_err;                /* n: the last step's weighted local error */
  double *g_prev;                  /* n_roots: the functions at the last step */
  double *sign_ref;                /* n_roots: their armed signs */
  double *g;                       /* n_roots: work */
  double *yp;                      /* n: y' at tn */
  double *fail_y;                  /* n: y of a singular iteration matrix */
  double *fail_yp;                 /* n: its y' */
  void *splu;                      /* the sparse LU (cbdf_sparse.c), or NULL */
  /* -- the model (mode 0): its generated functions and their layout ------------------- */
  void *residual_fn;               /* the generated residual (or the mode-1 callback) */
  void *jacobian_fn;               /* the generated Jacobian values (or the callback) */
  void *roots_fn;                  /* the generated relations (or the callback) */
  void *scales_fn;                 /* the generated scales of the relations */
  const double *par;               /* the parameter vector p */
  const double *m;                 /* the discrete state m */
  double *work;                    /* the generated functions' work array */
  double *model_out;               /* n_rows: the residual's output */
  int64_t n_res;                   /* residual rows G */
  int64_t n_state_rows;            /* rows der(s) - D(t, z) of the causal form */
  int64_t n_links;                 /* linking rows z'[s] - z[der(s)] */
  int64_t n_jac;                   /* Jacobian values */
  int64_t n_rel;                   /* relations */
  int64_t n_disc;                  /* frozen integer values */
  int64_t n_rows;                  /* the residual's outputs */
  const int64_t *jac_rows;         /* n_jac: row of each Jacobian value */
  const int64_t *jac_cols;         /* n_jac: its column */
  const double *jac_sign;          /* n_jac: +1 for dG/dz, -1 for -dD/dz */
  const int64_t *state_z;          /* n_state_rows: the unknown of each state row */
  const int64_t *link_s;           /* n_links: the state of each linking row */
  const int64_t *link_d;           /* n_links: its derivative's unknown */
  double *jac_values;              /* n_jac: work */
  const double *root_sign;         /* n_rel: the orientation of each relation */
  const double *root_side;         /* n_rel: the side it is judged on */
  const double *root_nominal;      /* n_rel: the scale below which it is zero */
  const double *timed;             /* n_rel + n_disc: 1 for a function of time alone */
  double *root_offset;             /* n_roots: offsets of items armed at zero */
  double *root_values;             /* n_rel + n_disc: work */
  double *root_scales;             /* n_rel: work */
  int64_t *dyn_longs;              /* the dynamic state sets' test (cbdf_dyn.c), or NULL */
  double *dyn_doubles;             /* its doubles */
} cbdf_state;

/* The generated functions' contract (acausal.compiler.backends.cbackend) */
typedef int (*cbdf_genfn)(double, const double *, const double *, const double *, double *,
                          double *);

CBDF_API int cbdf_run(cbdf_state *s);
CBDF_API const char *cbdf_source_digest(void);
CBDF_API void cbdf_interpolate(const cbdf_state *s, double t, double *y, double *yp);
CBDF_API int64_t cbdf_state_size(void);

CBDF_API int dense_factor(const double *J, double *A, int64_t *piv, double *r, double *c,
                          int64_t n, int *equil);
CBDF_API void dense_solve(const double *A, const int64_t *piv, const double *r,
                          const double *c, int64_t n, double *b);

CBDF_API void *sparse_new(int64_t n, const int64_t *Ap, const int64_t *Ai, int64_t nslot,
                          const int64_t *slot, const int64_t *q, const int64_t *pref,
                          int64_t cap);
CBDF_API void sparse_free(void *h);
CBDF_API double *sparse_values(void *h);
CBDF_API void sparse_jacobian(void *h, const double *v, const double *js, int64_t njac,
                              int64_t nsz, int64_t nl, double cj);
CBDF_API int sparse_factor(void *h);
CBDF_API void sparse_solve(void *h, double *b);
CBDF_API int64_t sparse_nnz(void *h);

CBDF_API int dyn_keeps(const double *vals, int64_t nv, const int64_t *dl, double *dd);
CBDF_API int dyn_due(int64_t *dl, double *dd, void *jac, double t, const double *y,
                     const double *p, const double *m, double *vals, double *w, int64_t nv);

#endif
