// Exact sign of the 2D orientation determinant, so coverage decisions in the reference renderer are
// exact for any double vertex coordinates (a shared edge is then evaluated as exactly the negation
// from both sides, and the fill rule can be applied without rounding).
#pragma once

namespace htx::ref {

// Sign (-1, 0, +1) of (bx - ax) * (cy - ay) - (by - ay) * (cx - ax), computed exactly.
int orient2d_sign(double ax, double ay, double bx, double by, double cx, double cy);

}  // namespace htx::ref
