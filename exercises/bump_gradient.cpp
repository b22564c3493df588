// exercises/bump_gradient.cpp — seed 002's bump map made into Blinn's normal.
//
// The statement.  Seed 002 bumps a torus with a height map, from its
// differences between neighbouring texels,
//     gx = j(x + 1, y) − j(x − 1, y),   gy = j(x, y + 1) − j(x, y − 1),
// and seed 004 gives Blinn's perturbed normal for a surface Q(u, w) displaced
// by P(u, w) along its normal n = Q_u × Q_w:
//     n' = n + P_u (n × Q_w)/|n| + P_w (Q_u × n)/|n|.
// Put the two together: turn the differences into P_u and P_w and write n'.
//
// Write: the bumped normal (any length: the checker normalises it) at a
// texel whose differences are gx and gy (heights in [0, 1]; the bump is
// scale · height, in the surface's units), for a texel `ds` wide in s and
// `dt` in t, where the surface has the partial derivatives Qs = ∂Q/∂s and
// Qt = ∂Q/∂t (world units per unit of s and of t).
//
// Checked like bump_mapping's normal error: on the torus of Figure VI.6
// (R = 1, r = 0.4) with the demo's dimples and ridges at its height scale
// 0.04, at 1,024 texel centres, your normal against the normal of the
// truly displaced surface Q + scale h N: the mean angle at most 1°.
#include "exercise.hpp"

glm::dvec3 exercise::bumpNormal(glm::dvec3 Qs, glm::dvec3 Qt, double gx, double gy, double ds, double dt,
                                double scale) {
  (void)Qs, (void)Qt, (void)gx, (void)gy, (void)ds, (void)dt, (void)scale;
  TS_EXERCISE_NOT_DONE("bump_gradient");
}
