// One start-up for SuiteSparse (CHOLMOD and KLU) wherever the library factors a sparse matrix
// (src/kinematics/sparse.c, src/mechanics/spd.c, src/flat/regularize.c, src/unfold/linkage.c):
// its memory goes through the library's counted allocator, it never prints, and CHOLMOD's own
// OpenMP loops run serially inside our calls.
#ifndef ORI_CORE_SUITESPARSE_H
#define ORI_CORE_SUITESPARSE_H

#include <cholmod.h>
#include <klu.h>

// Route SuiteSparse's memory through ori__alloc and friends. SuiteSparse_config is a global of
// SuiteSparse 5, so every entry point sets the same functions again before it allocates.
void ori__suitesparse_route_memory(void);
// Start a CHOLMOD workspace: memory routed, no printing, no error handler, a failed Cholesky
// returns at once (quick_return_if_not_posdef); the caller picks supernodal or simplicial.
void ori__cholmod_start(cholmod_common *cm);
// KLU's defaults, with its memory routed.
void ori__klu_start(klu_common *kc);
// Make CHOLMOD's OpenMP loops serial until ori__suitesparse_serial_end (pass it what this
// returns). Debian's CHOLMOD (SuiteSparse 5) runs them on a fixed 4 threads, whose start-up and
// spinning cost more than the loops at the sizes orikin factors (docs/compliant.md, section 6).
// The setting is the process's, restored at the end; nothing without GNU OpenMP.
int ori__suitesparse_serial_begin(void);
void ori__suitesparse_serial_end(int levels);

#endif
