// Private pieces of the unfolding module (src/unfold): the exact orientation predicate shared by
// the linkage motion (linkage.c) and the overlap test of nets (net.c).
#ifndef ORI_UNFOLD_INTERNAL_H
#define ORI_UNFOLD_INTERNAL_H

#include <orikin/math.h>

// Sign of the orientation of (a, b, c): +1 counter-clockwise, −1 clockwise, 0 collinear,
// exact for the given doubles (a floating-point filter, then GMP rationals when it cannot decide).
int ori__orient2d_exact(ori_v2 a, ori_v2 b, ori_v2 c);
// True when closed segments ab and cd intersect (exactly), touching included.
bool ori__segments_intersect(ori_v2 a, ori_v2 b, ori_v2 c, ori_v2 d);
// True when the segments cross at a single point interior to both (exactly).
bool ori__segments_cross_properly(ori_v2 a, ori_v2 b, ori_v2 c, ori_v2 d);
// Sign of the orientation of the points p_k + ε d[k] + ε² e[k] (p = a, b, c; d and e hold three
// directions each) for an infinitesimal ε > 0: the lowest non-zero coefficient of the polynomial
// in ε, each exact (Simulation of Simplicity with the given perturbation). Zero only when every
// coefficient vanishes.
int ori__orient2d_perturbed(ori_v2 a, ori_v2 b, ori_v2 c, const ori_v2 *d, const ori_v2 *e);

#endif
