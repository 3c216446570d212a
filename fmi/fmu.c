/* The FMI 2.0 functions (Model Exchange and Co-Simulation) of an exported acausal model,
   over the engine of engine.c and the integrator of cosim.c.  Only Real variables exist;
   FMU states (fmi2GetFMUstate ...) and directional derivatives are not supported
   (canGetAndSetFMUstate and providesDirectionalDerivative are false). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "fmi2Functions.h"
#include "acausal_fmu.h"

enum { INSTANTIATED, INITIALIZATION, EVENT, CONTINUOUS, STEPPING, TERMINATED, FAILED };

typedef struct {
    ac_state s;
    fmi2CallbackFunctions cb;
    char *name;
    fmi2Type type;
    int mode, logging;
    int initialized;      /* the initial system solved for the values set so far */
    double stop_time;
} instance;

static void say(instance *c, fmi2Status st, const char *category, const char *msg) {
    if (c->cb.logger && (c->logging || st != fmi2OK))
        c->cb.logger(c->cb.componentEnvironment, c->name, st, category, "%s", msg);
}

static fmi2Status fail(instance *c, const char *what) {
    char buf[700];
    snprintf(buf, sizeof buf, "%s: %s", what, c->s.message[0] ? c->s.message : "failed");
    say(c, fmi2Error, "logStatusError", buf);
    c->mode = FAILED;
    return fmi2Error;
}

static fmi2Status unsupported(fmi2Component comp, const char *what) {
    instance *c = (instance *)comp;
    char buf[200];
    snprintf(buf, sizeof buf, "%s is not supported by this FMU", what);
    if (c) say(c, fmi2Error, "logStatusError", buf);
    return fmi2Error;
}

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char *fmi2GetVersion(void) { return fmi2Version; }

fmi2Status fmi2SetDebugLogging(fmi2Component comp, fmi2Boolean on, size_t n,
                               const fmi2String cats[]) {
    (void)n; (void)cats;
    ((instance *)comp)->logging = on;
    return fmi2OK;
}

fmi2Component fmi2Instantiate(fmi2String name, fmi2Type type, fmi2String guid,
                              fmi2String location, const fmi2CallbackFunctions *cb,
                              fmi2Boolean visible, fmi2Boolean logging) {
    (void)location; (void)visible;
    if (!guid || strcmp(guid, AC_MODEL.guid) != 0) {
        if (cb && cb->logger)
            cb->logger(cb->componentEnvironment, name, fmi2Error, "logStatusError",
                       "GUID %s does not match this binary's %s", guid ? guid : "(null)",
                       AC_MODEL.guid);
        return NULL;
    }
    instance *c = (instance *)calloc(1, sizeof(instance));
    if (!c) return NULL;
    if (ac_alloc(&c->s, &AC_MODEL)) { ac_free(&c->s); free(c); return NULL; }
    if (cb) c->cb = *cb;
    c->name = (char *)malloc(strlen(name ? name : "") + 1);
    strcpy(c->name, name ? name : "");
    c->type = type;
    c->logging = logging;
    c->mode = INSTANTIATED;
    return c;
}

void fmi2FreeInstance(fmi2Component comp) {
    instance *c = (instance *)comp;
    if (!c) return;
    ac_free(&c->s);
    free(c->name);
    free(c);
}

fmi2Status fmi2SetupExperiment(fmi2Component comp, fmi2Boolean tol_defined, fmi2Real tol,
                               fmi2Real t0, fmi2Boolean stop_defined, fmi2Real stop) {
    instance *c = (instance *)comp;
    if (tol_defined && tol > 0) c->s.rtol = tol;
    c->s.t = t0;
    c->stop_time = stop_defined ? stop : INFINITY;
    return fmi2OK;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component comp) {
    instance *c = (instance *)comp;
    c->mode = INITIALIZATION;
    c->initialized = 0;
    return fmi2OK;
}

/* The initial system is solved when its values are first asked for in initialization
   mode (an importer may read the initial unknowns there), or on leaving it. */
static int ensure_initialized(instance *c) {
    if (c->initialized) return 0;
    if (ac_initialize(&c->s)) return -1;
    c->initialized = 1;
    return 0;
}

fmi2Status fmi2ExitInitializationMode(fmi2Component comp) {
    instance *c = (instance *)comp;
    if (ensure_initialized(c)) return fail(c, "fmi2ExitInitializationMode");
    c->mode = c->type == fmi2ModelExchange ? EVENT : STEPPING;
    return fmi2OK;
}

fmi2Status fmi2Terminate(fmi2Component comp) {
    instance *c = (instance *)comp;
    if (c->type == fmi2CoSimulation && c->logging) {
        char buf[200];
        snprintf(buf, sizeof buf, "integrator: %ld steps, %ld rejected, %ld events",
                 c->s.steps, c->s.rejected, c->s.events);
        say(c, fmi2OK, "logStatistics", buf);
    }
    c->mode = TERMINATED;
    return fmi2OK;
}

fmi2Status fmi2Reset(fmi2Component comp) {
    instance *c = (instance *)comp;
    ac_free(&c->s);
    if (ac_alloc(&c->s, &AC_MODEL)) return fail(c, "fmi2Reset");
    c->mode = INSTANTIATED;
    return fmi2OK;
}

/* -- variables ------------------------------------------------------------------------- */
/* The values of the variables at positions idx[0..n-1] of the table (fmi/export.py). */
static fmi2Status get_values(instance *c, const int *idx, size_t n, double value[],
                             const char *what) {
    const ac_model *md = c->s.md;
    int need_all = 0, need_der = 0;
    for (size_t i = 0; i < n; ++i) {
        need_all |= md->var_kind[idx[i]] == AC_EXPAND;
        need_der |= md->var_kind[idx[i]] == AC_DERIV;
    }
    if (c->mode == INSTANTIATED) need_all = need_der = 0;
    if (c->mode == INITIALIZATION && (need_all || need_der) && ensure_initialized(c))
        return fail(c, what);
    if (need_all && ac_expand(&c->s)) return fail(c, what);
    if (need_der && ac_derivatives(&c->s)) return fail(c, what);
    for (size_t i = 0; i < n; ++i) {
        int v = idx[i], k = md->var_index[v];
        switch (md->var_kind[v]) {
        case AC_PARAM: value[i] = c->s.p[k]; break;
        case AC_EXPAND:
            if (need_all) value[i] = md->var_sign[v] * c->s.all[k];
            else if (md->var_start[v] >= 0) value[i] = c->s.x_start[md->var_start[v]];
            else value[i] = md->var_value[v];
            break;
        case AC_DERIV: value[i] = need_der ? c->s.xdot[k] : 0.0; break;
        case AC_PAFFINE: value[i] = md->var_sign[v] * c->s.p[k] + md->var_value[v]; break;
        default: value[i] = md->var_value[v];
        }
    }
    return fmi2OK;
}

/* Table positions of value references of one type (first: its first position, count). */
static int positions(const fmi2ValueReference vr[], size_t n, int first, int count,
                     int *idx) {
    for (size_t i = 0; i < n; ++i) {
        if (vr[i] >= (fmi2ValueReference)count) return -1;
        idx[i] = first + (int)vr[i];
    }
    return 0;
}

static int n_int_vars(const ac_model *md) {
    return md->n_vars - md->n_real_vars - md->n_bool_vars;
}

static fmi2Status get_typed(fmi2Component comp, const fmi2ValueReference vr[], size_t n,
                            double *value, int first, int count, const char *what) {
    instance *c = (instance *)comp;
    int *idx = (int *)calloc(n ? n : 1, sizeof(int));
    if (!idx) return fail(c, what);
    fmi2Status st = positions(vr, n, first, count, idx)
        ? unsupported(comp, "this value reference") : get_values(c, idx, n, value, what);
    free(idx);
    return st;
}

fmi2Status fmi2GetReal(fmi2Component comp, const fmi2ValueReference vr[], size_t n,
                       fmi2Real value[]) {
    const ac_model *md = ((instance *)comp)->s.md;
    return get_typed(comp, vr, n, value, 0, md->n_real_vars, "fmi2GetReal");
}

fmi2Status fmi2GetInteger(fmi2Component comp, const fmi2ValueReference vr[], size_t n,
                          fmi2Integer v[]) {
    const ac_model *md = ((instance *)comp)->s.md;
    double *x = (double *)calloc(n ? n : 1, sizeof(double));
    if (!x) return fail((instance *)comp, "fmi2GetInteger");
    fmi2Status st = get_typed(comp, vr, n, x, md->n_real_vars + md->n_bool_vars,
                              n_int_vars(md), "fmi2GetInteger");
    for (size_t i = 0; st == fmi2OK && i < n; ++i) v[i] = (fmi2Integer)nearbyint(x[i]);
    free(x);
    return st;
}

fmi2Status fmi2GetBoolean(fmi2Component comp, const fmi2ValueReference vr[], size_t n,
                          fmi2Boolean v[]) {
    const ac_model *md = ((instance *)comp)->s.md;
    double *x = (double *)calloc(n ? n : 1, sizeof(double));
    if (!x) return fail((instance *)comp, "fmi2GetBoolean");
    fmi2Status st = get_typed(comp, vr, n, x, md->n_real_vars, md->n_bool_vars,
                              "fmi2GetBoolean");
    for (size_t i = 0; st == fmi2OK && i < n; ++i) v[i] = x[i] > 0.5 ? fmi2True : fmi2False;
    free(x);
    return st;
}

/* Parameters (and inputs) of any type, and before initialization a state's start value. */
static fmi2Status set_values(fmi2Component comp, const int *idx, size_t n,
                             const double value[]) {
    instance *c = (instance *)comp;
    const ac_model *md = c->s.md;
    for (size_t i = 0; i < n; ++i) {
        int r = idx[i];
        if (md->var_kind[r] == AC_PARAM)
            c->s.p[md->var_index[r]] = value[i];
        else if (md->var_start[r] >= 0
                 && (c->mode == INSTANTIATED || c->mode == INITIALIZATION))
            c->s.x_start[md->var_start[r]] = value[i];      /* a state's start value */
        else
            return unsupported(comp, "setting a variable that is not a parameter, an input "
                                     "or (before initialization) a state's start value");
    }
    c->initialized = 0;
    c->s.solved = 0;
    c->s.expanded = 0;
    return fmi2OK;
}

static fmi2Status set_typed(fmi2Component comp, const fmi2ValueReference vr[], size_t n,
                            const double *value, int first, int count) {
    int *idx = (int *)calloc(n ? n : 1, sizeof(int));
    if (!idx) return fail((instance *)comp, "setting a variable");
    fmi2Status st = positions(vr, n, first, count, idx)
        ? unsupported(comp, "this value reference") : set_values(comp, idx, n, value);
    free(idx);
    return st;
}

fmi2Status fmi2SetReal(fmi2Component comp, const fmi2ValueReference vr[], size_t n,
                       const fmi2Real value[]) {
    return set_typed(comp, vr, n, value, 0, ((instance *)comp)->s.md->n_real_vars);
}

fmi2Status fmi2SetInteger(fmi2Component comp, const fmi2ValueReference vr[], size_t n,
                          const fmi2Integer v[]) {
    const ac_model *md = ((instance *)comp)->s.md;
    double *x = (double *)calloc(n ? n : 1, sizeof(double));
    if (!x) return fail((instance *)comp, "fmi2SetInteger");
    for (size_t i = 0; i < n; ++i) x[i] = (double)v[i];
    fmi2Status st = set_typed(comp, vr, n, x, md->n_real_vars + md->n_bool_vars,
                              n_int_vars(md));
    free(x);
    return st;
}

fmi2Status fmi2SetBoolean(fmi2Component comp, const fmi2ValueReference vr[], size_t n,
                          const fmi2Boolean v[]) {
    const ac_model *md = ((instance *)comp)->s.md;
    double *x = (double *)calloc(n ? n : 1, sizeof(double));
    if (!x) return fail((instance *)comp, "fmi2SetBoolean");
    for (size_t i = 0; i < n; ++i) x[i] = v[i] ? 1.0 : 0.0;
    fmi2Status st = set_typed(comp, vr, n, x, md->n_real_vars, md->n_bool_vars);
    free(x);
    return st;
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2String v[]) {
    (void)vr; (void)v; return n ? unsupported(c, "a String variable") : fmi2OK;
}
fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2String v[]) {
    (void)vr; (void)v; return n ? unsupported(c, "a String variable") : fmi2OK;
}

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *st) { (void)st; return unsupported(c, "fmi2GetFMUstate"); }
fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate st) { (void)st; return unsupported(c, "fmi2SetFMUstate"); }
fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *st) { (void)st; return unsupported(c, "fmi2FreeFMUstate"); }
fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate st, size_t *n) {
    (void)st; (void)n; return unsupported(c, "fmi2SerializedFMUstateSize");
}
fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate st, fmi2Byte b[], size_t n) {
    (void)st; (void)b; (void)n; return unsupported(c, "fmi2SerializeFMUstate");
}
fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte b[], size_t n, fmi2FMUstate *st) {
    (void)st; (void)b; (void)n; return unsupported(c, "fmi2DeSerializeFMUstate");
}
fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference u[], size_t nu,
                                        const fmi2ValueReference z[], size_t nz,
                                        const fmi2Real dv[], fmi2Real dz[]) {
    (void)u; (void)nu; (void)z; (void)nz; (void)dv; (void)dz;
    return unsupported(c, "fmi2GetDirectionalDerivative");
}

/* -- Model Exchange ---------------------------------------------------------------------- */
fmi2Status fmi2EnterEventMode(fmi2Component comp) {
    ((instance *)comp)->mode = EVENT;
    return fmi2OK;
}

fmi2Status fmi2NewDiscreteStates(fmi2Component comp, fmi2EventInfo *info) {
    instance *c = (instance *)comp;
    int changed = 0;
    if (ac_event(&c->s, &changed)) return fail(c, "fmi2NewDiscreteStates");
    info->newDiscreteStatesNeeded = fmi2False;      /* iterated to a fixed point inside */
    info->terminateSimulation = fmi2False;
    info->nominalsOfContinuousStatesChanged = fmi2False;
    info->valuesOfContinuousStatesChanged = changed ? fmi2True : fmi2False;
    info->nextEventTimeDefined = c->s.has_next_time ? fmi2True : fmi2False;
    info->nextEventTime = c->s.has_next_time ? c->s.next_time : 0.0;
    return fmi2OK;
}

fmi2Status fmi2EnterContinuousTimeMode(fmi2Component comp) {
    ((instance *)comp)->mode = CONTINUOUS;
    return fmi2OK;
}

fmi2Status fmi2CompletedIntegratorStep(fmi2Component comp, fmi2Boolean no_set_prior,
                                       fmi2Boolean *enter_event, fmi2Boolean *terminate) {
    (void)no_set_prior;
    ac_release(&((instance *)comp)->s);
    *enter_event = fmi2False;
    *terminate = fmi2False;
    return fmi2OK;
}

fmi2Status fmi2SetTime(fmi2Component comp, fmi2Real t) {
    instance *c = (instance *)comp;
    c->s.t = t;
    c->s.solved = 0;
    return fmi2OK;
}

fmi2Status fmi2SetContinuousStates(fmi2Component comp, const fmi2Real x[], size_t nx) {
    instance *c = (instance *)comp;
    for (size_t i = 0; i < nx && i < (size_t)c->s.md->n_x; ++i)
        c->s.z[c->s.md->state_index[i]] = x[i];
    c->s.solved = 0;
    return fmi2OK;
}

fmi2Status fmi2GetDerivatives(fmi2Component comp, fmi2Real dx[], size_t nx) {
    instance *c = (instance *)comp;
    if (ac_derivatives(&c->s)) return fail(c, "fmi2GetDerivatives");
    for (size_t i = 0; i < nx && i < (size_t)c->s.md->n_x; ++i) dx[i] = c->s.xdot[i];
    return fmi2OK;
}

fmi2Status fmi2GetEventIndicators(fmi2Component comp, fmi2Real ind[], size_t ni) {
    instance *c = (instance *)comp;
    if (ni == 0) return fmi2OK;
    if (ac_oriented(&c->s, ind)) return fail(c, "fmi2GetEventIndicators");
    return fmi2OK;
}

fmi2Status fmi2GetContinuousStates(fmi2Component comp, fmi2Real x[], size_t nx) {
    instance *c = (instance *)comp;
    for (size_t i = 0; i < nx && i < (size_t)c->s.md->n_x; ++i)
        x[i] = c->s.z[c->s.md->state_index[i]];
    return fmi2OK;
}

fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component comp, fmi2Real x[], size_t nx) {
    instance *c = (instance *)comp;
    for (size_t i = 0; i < nx && i < (size_t)c->s.md->n_x; ++i)
        x[i] = c->s.md->nominal[c->s.md->state_index[i]];
    return fmi2OK;
}

/* -- Co-Simulation ------------------------------------------------------------------------ */
fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                                       const fmi2Integer order[], const fmi2Real v[]) {
    (void)vr; (void)order; (void)v; return n ? unsupported(c, "input derivatives") : fmi2OK;
}
fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                                        const fmi2Integer order[], fmi2Real v[]) {
    (void)vr; (void)order; (void)v; return n ? unsupported(c, "output derivatives") : fmi2OK;
}

fmi2Status fmi2DoStep(fmi2Component comp, fmi2Real t, fmi2Real h, fmi2Boolean no_set_prior) {
    instance *c = (instance *)comp;
    (void)no_set_prior;
    if (fabs(t - c->s.t) > 1e-9 * fmax(1.0, fabs(t))) {
        snprintf(c->s.message, sizeof c->s.message,
                 "the communication point %.10g is not the FMU's time %.10g", t, c->s.t);
        return fail(c, "fmi2DoStep");
    }
    c->s.t = t;
    if (ac_do_step(&c->s, t + h)) return fail(c, "fmi2DoStep");
    c->s.t = t + h;
    return fmi2OK;
}

fmi2Status fmi2CancelStep(fmi2Component c) { return unsupported(c, "fmi2CancelStep"); }

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind k, fmi2Status *v) {
    (void)k; *v = fmi2OK; (void)c; return fmi2OK;
}
fmi2Status fmi2GetRealStatus(fmi2Component comp, const fmi2StatusKind k, fmi2Real *v) {
    if (k != fmi2LastSuccessfulTime) return unsupported(comp, "this status");
    *v = ((instance *)comp)->s.t;
    return fmi2OK;
}
fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind k, fmi2Integer *v) {
    (void)k; (void)v; return unsupported(c, "fmi2GetIntegerStatus");
}
fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind k, fmi2Boolean *v) {
    (void)k; (void)v; return unsupported(c, "fmi2GetBooleanStatus");
}
fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind k, fmi2String *v) {
    (void)k; (void)v; return unsupported(c, "fmi2GetStringStatus");
}
