# Source of exercises/hw02_beta_constraints.ipynb and solutions/hw02_beta_constraints.ipynb.
# Edit here, then run `python tools/build_homework.py` (format: see that script's docstring).
# ruff: noqa: B018

# %% [markdown]
# *Geometric continuity of parametric curves* · Homework 2 of 5 · after the lecture
# [03 Beta-constraints](../notebooks/03_beta_constraints.ipynb) and [04 Arc length and Theorem 1](../notebooks/04_arc_length_and_theorem_1.ipynb) (seed 000 §5–7, seed 001 eq. 2.7).
#
# # Homework 2 — The Beta-constraints
#
# Two regular parametrizations $\mathbf q(u)$, $u \in [0, 1]$, and $\mathbf r(t)$, $t \in [0, 1]$,
# meeting at $\mathbf r(0) = \mathbf q(1)$ are $G^n$ exactly when there are shape parameters
# $\beta_1 > 0, \beta_2, \dots, \beta_n$ satisfying the Beta-constraints (seed 000 eq. 7):
#
# $$\mathbf r'(0) = \beta_1 \mathbf q'(1), \qquad
#   \mathbf r''(0) = \beta_1^2 \mathbf q''(1) + \beta_2 \mathbf q'(1), \qquad \dots$$
#
# You will read shape parameters off derivative vectors, test for $G^1$, derive a higher
# constraint with sympy, and read continuity off a picture.
#
# **How to work.** Replace each `...` by your answer (or write the body of the function), run the
# cell, then run the **check cell** below it: ✓ right, ✗ what is wrong, … not answered yet.
# On q5, ? means the form is right but this copy of the course has no answer key for your data:
# only the grader checks the value (check `VARIANT`; if it is your code, tell your instructor).
# The checks are feedback; the grade comes from the grader's own tests, on your data and, for
# the functions, on other data too. Keep the names, do not delete cells, and before you hand in
# run *Kernel → Restart Kernel and Run All Cells*.
# Numbers are checked and graded to about 9 decimals: compute them in Python from `DATA`; a
# rounded number you type in is wrong.
# Multiple-choice questions are for practice, worth 0 points: a letter can be found by trying
# each one in its check.
#
# **Your own work.** Points are for what you write yourself. A function you write must not call
# the `course_lib` function that already does it (each function question says what you may
# use): while your function is checked or graded, those library functions raise an error --
# "… is the exercise of hw02.q3: write it yourself" -- and the question earns 0 points. The
# checks do not hand out answers either: they say ✓ or ✗, and what kind of case went wrong.
# The check of q5 does not even know the value: it compares a fingerprint of your answer with
# one your instructor made from the grader's tests.
#
# **Your own data.** Every student gets their own numbers: paste the *variant code* your
# instructor gave you into `VARIANT` below. The cells marked "your data" print the data of each
# question; your code should use `DATA[...]` rather than typing the numbers. With `VARIANT = ""`
# you get the example data (fine for practice, but graded on your own data it scores nothing).

# %% [markdown]
# ## Preparations

# %%
import matplotlib.pyplot as plt
import numpy as np
import sympy as sp

from course_lib import PiecewiseBezier
from course_lib.homework import variants
from course_lib.homework.checks import check, check_all
from course_lib.plotting import segment_color

HOMEWORK = "hw02"
VARIANT = ""  # paste the code your instructor gave you, e.g. VARIANT = "KQW7MZP3XS"
DATA = variants.data(HOMEWORK, VARIANT)
beta1, beta2, beta3, beta4 = sp.symbols("beta1:5")

# %% [markdown]
# ## Question 1 — β1 from two tangents (compute)
#
# At a joint, the end tangent $\mathbf q'(1)$ and the start tangent $\mathbf r'(0)$ of your data
# (printed below) satisfy (7.1). Find $\beta_1$.

# %%
print(DATA["q1"]["text"])  # your data

# %%
q1, r1 = np.array(DATA["q1"]["q1"]), np.array(DATA["q1"]["r1"])
### BEGIN SOLUTION
answer_q1 = np.linalg.norm(r1) / np.linalg.norm(q1)
assert np.allclose(r1, answer_q1 * q1)  # (7.1) really holds: the joint is G1
### END SOLUTION
### STUDENT answer_q1 = ...

# %%
check("hw02.q1", answer_q1)

# %% [markdown]
# ## Question 2 — β1 and β2 from two derivatives (compute)
#
# At another joint you are given $\mathbf q'(1)$, $\mathbf q''(1)$, $\mathbf r'(0)$ and
# $\mathbf r''(0)$ (your data, below). Find $\beta_1$ and $\beta_2$ such that (7.1) and (7.2)
# hold; answer `np.array([beta1_value, beta2_value])`.

# %%
print(DATA["q2"]["text"])  # your data

# %%
d = DATA["q2"]
q1, q2, r1, r2 = (np.array(d[name]) for name in ("q1", "q2", "r1", "r2"))
### BEGIN SOLUTION
b1 = np.dot(r1, q1) / np.dot(q1, q1)
b2 = np.dot(r2 - b1**2 * q2, q1) / np.dot(q1, q1)  # (7.2): r'' - β1² q'' must be β2 q'
assert np.allclose(r2, b1**2 * q2 + b2 * q1)
answer_q2 = np.array([b1, b2])
### END SOLUTION
### STUDENT answer_q2 = ...

# %%
check("hw02.q2", answer_q2)

# %% [markdown]
# ## Question 3 — a G1 test (write a function)
#
# Write `is_g1(q1, r1, tol=1e-9)` that returns `True` when the end tangent $\mathbf q'(1)$ and the
# start tangent $\mathbf r'(0)$ (numpy arrays in the plane or in space) satisfy (7.1) for some
# $\beta_1 > 0$, and `False` otherwise. Compare *directions* (the tolerance is for unit vectors),
# so that very long and very short vectors are handled alike. A zero vector is not regular:
# return `False`.
#
# **You may use:** numpy (and plain Python); no function of `course_lib`.
# `course_lib.geometry.beta_constraints.solve_shape_parameters`,
# `course_lib.geometry.continuity.joint_continuity`, `course_lib.geometry.continuity.curve_continuity` do it for
# you, so they raise while your function is checked or graded.

# %%
def is_g1(q1, r1, tol=1e-9):
    """True if r1 = beta1 * q1 for some beta1 > 0."""
    ### BEGIN SOLUTION
    q1, r1 = np.asarray(q1, dtype=float), np.asarray(r1, dtype=float)
    nq, nr = np.linalg.norm(q1), np.linalg.norm(r1)
    if nq == 0 or nr == 0:
        return False
    return bool(np.linalg.norm(q1 / nq - r1 / nr) <= tol)
    ### END SOLUTION
    ### STUDENT raise NotImplementedError("write the body of is_g1")

# %%
check("hw02.q3", is_g1)

# %% [markdown]
# ## Question 4 — the fourth Beta-constraint (derive with sympy)
#
# Write $\bar{\mathbf q}(s) = \mathbf q(u(s))$ with $u(1) = 1$ and $\beta_j = u^{(j)}(1)$. The
# fourth derivative $\bar{\mathbf q}''''(1)$ is a combination of $\mathbf q'(1), \dots,
# \mathbf q''''(1)$. Derive, **with sympy**, the coefficient of $\mathbf q''(1)$, as an expression
# in the symbols `beta1, ..., beta4` of the Preparations cell.
#
# *Hint:* stand-ins make it concrete: $\mathbf q(x) = \sum_k c_k (x-1)^k / k!$ has
# $\mathbf q^{(k)}(1) = c_k$, and $u(s) = 1 + \sum_j \beta_j (s-1)^j / j!$ has $u^{(j)}(1) = \beta_j$.
# Compare your result with seed 001 eq. (2.7): trust the derivation, not the print.

# %%
### BEGIN SOLUTION
s = sp.Symbol("s")
c = sp.symbols("c1:5")  # c_k stands for q^(k)(1)
betas = (beta1, beta2, beta3, beta4)
u_of_s = 1 + sum(b * (s - 1) ** j / sp.factorial(j) for j, b in enumerate(betas, start=1))
q_of_u = sum(ck * (u_of_s - 1) ** k / sp.factorial(k) for k, ck in enumerate(c, start=1))
fourth = sp.expand(sp.diff(q_of_u, s, 4).subs(s, 1))
answer_q4 = fourth.coeff(c[1])
### END SOLUTION
### STUDENT answer_q4 = ...
answer_q4

# %%
check("hw02.q4", answer_q4)

# %% [markdown]
# ## Question 5 — stitching by the second constraint (compute)
#
# Given $\mathbf q'(1)$, $\mathbf q''(1)$, $\beta_1$ and $\beta_2$ of your data: which second
# derivative $\mathbf r''(0)$ must the next segment have for $G^2$ continuity?

# %%
print(DATA["q5"]["text"])  # your data

# %%
q1, q2 = np.array(DATA["q5"]["q1"]), np.array(DATA["q5"]["q2"])
b1, b2 = DATA["q5"]["beta1"], DATA["q5"]["beta2"]
### BEGIN SOLUTION
answer_q5 = b1**2 * q2 + b2 * q1
### END SOLUTION
### STUDENT answer_q5 = ...

# %%
check("hw02.q5", answer_q5)

# %% [markdown]
# ## Question 6 — the special values (multiple choice, feedback only: 0 points)
#
# At a joint the Beta-constraints hold with $\beta_1 = 1$ and $\beta_2 = 0$. Which one of the
# four statements of your data (in your own order) is true? Answer with one letter.

# %%
print(DATA["q6"]["text"])  # your data

# %%
### BEGIN SOLUTION
# (7) with β1 = 1, β2 = 0 reads r'(0) = q'(1), r''(0) = q''(1): C² continuity
right = "the two parametrizations meet with C² continuity there"
answer_q6 = "".join(x for x, label in DATA["q6"]["options"].items() if label == right)
### END SOLUTION
### STUDENT answer_q6 = ...

# %%
check("hw02.q6", answer_q6)

# %% [markdown]
# ## Question 7 — read a picture (multiple choice, feedback only: 0 points)
#
# The curve below has four cubic segments and three joints, lettered A, B, C in the order of your
# data. Under it, along the parameter and with one colour per segment: the direction angle of
# its unit tangent, and its signed curvature. **Which joint is $G^1$ but not $G^2$?** Answer with
# one letter.

# %%
print(DATA["q7"]["text"])  # your data

# %%
### ALT Three panels. Top: your curve, its segments in alternating blue and brown, each
### ALT joint a black dot with its letter. Below, along the parameter with the joints' letters on
### ALT the axis: the tangent direction in degrees (left) and the signed curvature (right), one
### ALT line per segment; a jump in the left panel is a corner, a jump only in the right one is G1.
segments_q7, labels_q7 = DATA["q7"]["segments"], DATA["q7"]["labels"]
curve_q7 = PiecewiseBezier(segments_q7)
fig, axes = plt.subplot_mosaic([["curve", "curve"], ["angle", "kappa"]], figsize=(8.8, 4.6),
                               layout="constrained", height_ratios=[0.8, 1])
ax_curve, ax_angle, ax_kappa = axes["curve"], axes["angle"], axes["kappa"]
uu = np.linspace(0.0, 1.0, 200)
for i in range(curve_q7.n_segments):
    p, d1, d2 = (curve_q7.evaluate_segment(i, uu, n) for n in (0, 1, 2))
    angle = np.degrees(np.arctan2(d1[:, 1], d1[:, 0]))
    kappa = (d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]) / np.linalg.norm(d1, axis=1) ** 3
    ax_curve.plot(p[:, 0], p[:, 1], lw=2, color=segment_color(i))
    ax_angle.plot(i + uu, angle, lw=2, color=segment_color(i))
    ax_kappa.plot(i + uu, kappa, lw=2, color=segment_color(i))
for name, (x, y) in zip(labels_q7, curve_q7.joint_points, strict=True):
    ax_curve.plot(x, y, "ko", ms=4)
    ax_curve.annotate(name, (x, y), xytext=(0, 8), textcoords="offset points", ha="center")
for ax, title in ((ax_angle, "tangent direction (degrees)"), (ax_kappa, "signed curvature κ")):
    ax.set_xticks(curve_q7.joint_parameters, list(labels_q7))
    ax.grid(axis="x", ls=":")
    ax.set_title(title)
    ax.set_xlabel("joint")
ax_curve.set_aspect("equal")
ax_curve.set_title("the curve", pad=16)
plt.show()

# %%
### BEGIN SOLUTION
answer_q7 = labels_q7[0]  # the first joint along the curve (see below)
### END SOLUTION
### STUDENT answer_q7 = ...

# %%
check("hw02.q7", answer_q7)

# %% [markdown] solution
# Along the curve: at the first joint the tangent direction is continuous but κ jumps: $G^1$, not
# $G^2$. At the second the two segments are the two halves of one cubic (de Casteljau
# subdivision), so everything is continuous. At the third the tangent direction jumps by 45°: a
# corner, not even $G^1$ — a jump of κ alone does not tell a corner from a $G^1$ joint. (With the
# example data the joints are A, B, C; every variant letters them in its own order.)

# %% [markdown]
# ## Check everything
#
# Run this last cell before you hand in: it checks every answer at once.

# %%
report = check_all(globals(), HOMEWORK)
### BEGIN SOLUTION
assert report.all_passed, report
### END SOLUTION
report

# %% [markdown]
# ## Hand in
#
# Save the notebook, then hand it in with **one** of these. For `your-id` use the id your instructor
# gave you with your variant code (your id on the course roster, e.g. your student number / SIS id):
#
# * in a terminal, from the course folder: `make submit HW=hw02 STUDENT=your-id`
# * in a new cell here: `from course_lib.homework.submit import submit; submit("hw02_beta_constraints.ipynb", student="your-id")`
#
# Either runs the notebook top to bottom in a fresh kernel, as the grader will, lists the cells that
# fail, and writes `submissions/hw02-your-id.ipynb`. Upload that file. The checks above are feedback;
# your grade comes from the grader's own tests, on your data (and, for functions, other data).
