"""The mathematics of a curve: what the analysis functions compute from any ``CurveLike``.

* :mod:`~course_lib.geometry.differential_geometry` -- tangent, normal, curvature, speed,
  osculating circle, the curve from its curvature (seed 004 §19.2-19.3);
* :mod:`~course_lib.geometry.arc_length` -- the one arc-length engine: Gauss-Legendre
  quadrature of the speed (one cached rule), exact per-segment lengths of Bézier curves;
* :mod:`~course_lib.geometry.sampling` -- a curve sampled for pictures (grids with one-sided
  joints, derivatives on fixed grids);
* :mod:`~course_lib.geometry.chain_rule` -- Bell polynomials: derivatives of a composition;
* :mod:`~course_lib.geometry.reparametrization`,
  :mod:`~course_lib.geometry.joint_reparametrization` -- changes of variables;
* :mod:`~course_lib.geometry.beta_constraints` -- the Beta-constraints of any order;
* :mod:`~course_lib.geometry.continuity` -- C- and G-order of a joint and of a curve;
* :mod:`~course_lib.geometry.closeness` -- how close two curves are (distance, angle,
  curvature).

No module here imports matplotlib or ipywidgets; sympy is imported inside the functions
that need it.
"""
