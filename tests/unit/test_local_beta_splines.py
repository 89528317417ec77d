"""G^n Beta-splines of degree n + 1 with each interior joint's own (β1, ..., βn) (issue 14).

References: the Beta-constraints typed in from seed 000 eq. (7.1)-(7.4) at every joint with
that joint's own β's (``_spline_checks.check_joint``, n <= 4); for n = 5 the continuity
report's β's (solved from the derivatives, order by order); the global construction when
all joints are equal; and the partition of unity (a constant polygon gives a point)."""

from __future__ import annotations

import numpy as np
import pytest
from _spline_checks import check_joint
from hypothesis import given, settings
from hypothesis import strategies as st

from course_lib.constructions.beta_splines import beta_spline, quartic_beta_spline
from course_lib.geometry.continuity import curve_continuity


def _joint_betas(rng, joints, n):
    jb = rng.uniform(-1.0, 1.0, size=(joints, n))
    jb[:, 0] = rng.uniform(0.4, 2.5, size=joints)
    return jb


@settings(max_examples=15, deadline=None)
@given(seed=st.integers(0, 10**6), n=st.integers(2, 4), extra=st.integers(2, 4))
def test_each_joint_has_its_own_betas(seed, n, extra):
    rng = np.random.default_rng(seed)
    d = n + 1
    V = rng.normal(size=(d + 1 + extra, 2))
    S = V.shape[0] - d
    jb = _joint_betas(rng, S - 1, n)
    c = beta_spline(V, jb, n)
    assert c.n_segments == S and c.degrees == (d,) * S
    for j in range(c.n_joints):
        check_joint(c, j, list(jb[j]), rtol=1e-8)
    # partition of unity: moving every control point by the same vector moves the curve
    shifted = beta_spline(V + np.array([3.0, -2.0]), jb, n)
    for a, b in zip(c.segments, shifted.segments, strict=True):
        np.testing.assert_allclose(b - a, np.broadcast_to([3.0, -2.0], a.shape), atol=1e-9)


def test_quartic_with_per_joint_beta1_beta2_beta3():
    rng = np.random.default_rng(7)
    V = rng.normal(size=(9, 2))  # 5 segments, 4 joints
    b1 = np.array([0.6, 1.8, 1.0, 2.5])
    b2 = np.array([0.0, 3.0, -1.0, 10.0])
    b3 = 0.5  # broadcast
    c = quartic_beta_spline(V, b1, b2, b3)
    for j in range(4):
        check_joint(c, j, [b1[j], b2[j], 0.5], rtol=1e-8)
    np.testing.assert_allclose(c.info["beta2"], b2)
    reps = curve_continuity(c, 3)
    assert all(r.g_order == 3 and r.characterizations_agree for r in reps)


@pytest.mark.parametrize("n", [2, 3, 5])
def test_equal_joints_reduce_to_the_global_form(n):
    rng = np.random.default_rng(n)
    V = rng.normal(size=(n + 6, 2))
    g = tuple(_joint_betas(rng, 1, n)[0])
    S = V.shape[0] - n - 1
    a = beta_spline(V, g, n)
    b = beta_spline(V, np.tile(g, (S - 1, 1)), n)
    for x, y in zip(a.segments, b.segments, strict=True):
        np.testing.assert_array_equal(x, y)


def test_order_five_per_joint_through_the_multiprecision_path():
    rng = np.random.default_rng(11)
    n = 5
    V = rng.normal(size=(n + 5, 2))
    jb = _joint_betas(rng, V.shape[0] - n - 2, n) * [1, 0.3, 0.3, 0.3, 0.3]
    c = beta_spline(V, jb, n)
    for j, rep in enumerate(curve_continuity(c, n, rtol=1e-7)):
        assert rep.g_order == n, (j, rep.g_order_by)
        np.testing.assert_allclose(rep.betas, jb[j], rtol=1e-6, atol=1e-6)


def test_bad_per_joint_input():
    V = np.random.default_rng(0).normal(size=(9, 2))
    with pytest.raises(ValueError, match=r"shape \(4, 3\)"):
        beta_spline(V, np.ones((3, 3)), 3)
    with pytest.raises(ValueError, match=r"at joint 2 it is -1\.0"):
        beta_spline(V, [[1, 0, 0], [1, 0, 0], [-1, 0, 0], [1, 0, 0]], 3)
    with pytest.raises(ValueError, match="beta2 must be a scalar or one value per interior joint"):
        quartic_beta_spline(V, 1.0, [0.0, 1.0])
