/* The compiled BDF step loop as one translation unit (the library acausal.solvers.cbdf
   loads): the dense LU, the dynamic state selection's test and the sparse LU come
   before the loop that calls them. */
#include "cbdf_lu.c"
#include "cbdf_dyn.c"
#include "cbdf_sparse.c"
#include "cbdf.c"
