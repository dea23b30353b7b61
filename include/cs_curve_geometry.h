/* Kernels on the positions of a distributed curve (include/cs_curve.h), crane2013 Sec. 5.2: edge lengths
   l_i = |f_{i+1} - f_i| (edge i from vertex i to i+1), dual lengths d_i = (l_{i-1} + l_i)/2 (the measure of
   the inner product <a,b> = sum_i d_i a_i b_i), signed turning angles phi_i at the vertices (the angle from
   edge i-1 to edge i in (-pi, pi]; zero at the ends of an open curve). Collective. */
#ifndef CS_CURVE_GEOMETRY_H
#define CS_CURVE_GEOMETRY_H
#include "cs_curve.h"

PETSC_EXTERN PetscErrorCode CSCurveEdgeLengths(CSCurve curve, Vec x, Vec len);
PETSC_EXTERN PetscErrorCode CSCurveDualLengths(CSCurve curve, Vec len, Vec d);
PETSC_EXTERN PetscErrorCode CSCurveTurningAngles(CSCurve curve, Vec x, Vec phi);
/* kappa_i = phi_i / d_i: the pointwise curvature whose cumulative sums (Sec. 5.2) give back the edge angles */
PETSC_EXTERN PetscErrorCode CSCurveCurvature(CSCurve curve, Vec x, Vec d, Vec kappa);
/* the angle of edge 0 (from vertex 0 to 1), on every rank */
PETSC_EXTERN PetscErrorCode CSCurveFirstEdgeAngle(CSCurve curve, Vec x, PetscReal *theta0);
/* sum_i w_i a_i b_i over the whole curve (w = NULL: plain sum) */
PETSC_EXTERN PetscErrorCode CSCurveDot(CSCurve curve, Vec w, Vec a, Vec b, PetscReal *dot);

#endif
