# Source of exercises/hw03_g1_knot_bezier_splines.ipynb and solutions/hw03_g1_knot_bezier_splines.ipynb.
# Edit here, then run `python tools/build_homework.py` (format: see that script's docstring).
# ruff: noqa: B018

# %% [markdown]
# *Geometric continuity of parametric curves* · Homework 3 of 5 · after the lecture
# [06 G1 Bézier splines from knots](../notebooks/06_g1_knot_bezier_splines.ipynb) (seed 004 §19.5–19.8).
#
# # Homework 3 — G1 Bézier splines from a knot sequence
#
# Finn builds a cubic $G^1$ spline from $2L + 2$ control points $\mathbf d_{-1}, \mathbf d_0,
# \dots, \mathbf d_{2L}$ and a knot sequence $t_0 < t_1 < \dots < t_L$. The Bézier control points
# are $\mathbf p_0, \mathbf p_1, \mathbf p_2 = \mathbf d_{-1}, \mathbf d_0, \mathbf d_1$, then
# $\mathbf p_{3i+1} = \mathbf d_{2i}$, $\mathbf p_{3i+2} = \mathbf d_{2i+1}$ for
# $i = 1, \dots, L-1$, and $\mathbf p_{3L} = \mathbf d_{2L}$; each joint point takes the
# barycentric coordinates of $t_i$ with respect to $t_{i-1}, t_{i+1}$:
#
# $$\mathbf p_{3i} = \frac{t_{i+1} - t_i}{t_{i+1} - t_{i-1}}\,\mathbf p_{3i-1}
#   + \frac{t_i - t_{i-1}}{t_{i+1} - t_{i-1}}\,\mathbf p_{3i+1}.$$
#
# This homework works through Finn's exercises 19.8.2 and 19.8.3 with our own data.
#
# **How to work.** Replace each `...` by your answer (or write the body of the function), run the
# cell, then run the **check cell** below it: ✓ right, ✗ what is wrong, … not answered yet.
# The checks are feedback; the grade comes from the grader's own tests, on your data and, for
# the functions, on other data too. Keep the names, do not delete cells, and before you hand in
# run *Kernel → Restart Kernel and Run All Cells*.
# Multiple-choice questions are for practice, worth 0 points: a letter can be found by trying
# each one in its check.
#
# **Your own work.** Points are for what you write yourself. A function you write must not call
# the `course_lib` function that already does it (each function question says what you may
# use): while your function is checked or graded, those library functions raise an error --
# "… is the exercise of hw03.q7: write it yourself" -- and the question earns 0 points. The
# checks do not hand out answers either: they say ✓ or ✗, and what kind of case went wrong.
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
from course_lib.plotting import new_figure

HOMEWORK = "hw03"
VARIANT = ""  # paste the code your instructor gave you, e.g. VARIANT = "KQW7MZP3XS"
DATA = variants.data(HOMEWORK, VARIANT)

# Finn's G1 control points d_-1, d_0, ..., d_6 for L = 3 segments (row j holds d_{j-1})
D = np.array(DATA["D"]["points"])
print(DATA["D"]["text"])  # your data

# %% [markdown]
# ## Question 1 — one joint point (compute)
#
# With the knots $t_0, t_1, t_2$ of your data (`DATA["q1"]["knots"]`), compute the joint point
# $\mathbf p_3$ between $\mathbf p_2 = \mathbf d_1$ and $\mathbf p_4 = \mathbf d_2$.

# %%
print(DATA["q1"]["text"])  # your data

# %%
### BEGIN SOLUTION
t0, t1, t2 = DATA["q1"]["knots"]
answer_q1 = ((t2 - t1) * D[2] + (t1 - t0) * D[3]) / (t2 - t0)
### END SOLUTION
### STUDENT answer_q1 = ...

# %%
check("hw03.q1", answer_q1)

# %% [markdown]
# ## Question 2 — all control points (write a function)
#
# Write `g1_bezier_control_points(d, knots)`: from the $2L + 2$ G1 control points `d` (an array of
# shape `(2L + 2, dim)`, row $j$ holding $\mathbf d_{j-1}$) and the $L + 1$ knots, return the
# $3L + 1$ Bézier control points $\mathbf p_0, \dots, \mathbf p_{3L}$ as an array of shape
# `(3L + 1, dim)`. It must work for any $L \ge 1$ and in space too.
#
# **You may use:** numpy (and plain Python); no function of `course_lib`.
# `course_lib.constructions.knot_splines.bezier_points_from_g1`, `course_lib.constructions.knot_splines.g1_knot_spline` do
# it for you, so they raise while your function is checked or graded.

# %%
def g1_bezier_control_points(d, knots):
    """Bézier control points p_0 .. p_{3L} of Finn's G1 spline (seed 004 §19.6)."""
    ### BEGIN SOLUTION
    d, t = np.asarray(d, dtype=float), np.asarray(knots, dtype=float)
    L = t.size - 1
    p = np.empty((3 * L + 1, d.shape[1]))
    p[[0, 1, 2]] = d[:3]
    for i in range(1, L):
        p[3 * i + 1], p[3 * i + 2] = d[2 * i + 1], d[2 * i + 2]
    p[3 * L] = d[2 * L + 1]
    for i in range(1, L):
        before, after = t[i] - t[i - 1], t[i + 1] - t[i]
        p[3 * i] = (after * p[3 * i - 1] + before * p[3 * i + 1]) / (before + after)
    return p
    ### END SOLUTION
    ### STUDENT raise NotImplementedError("write the body of g1_bezier_control_points")

# %%
check("hw03.q2", g1_bezier_control_points)

# %% [markdown]
# ## Question 3 — Finn's exercise 19.8.2 with three knot sequences (compute)
#
# For the control points `D` of the Preparations cell, construct the C0 Bézier control points
# for the three knot sequences (a), (b), (c) of your data (`DATA["q3"]["knots"]`), and answer
# with the list `[P_a, P_b, P_c]` (each of shape `(10, 2)`).

# %%
print(DATA["q3"]["text"])  # your data

# %%
knots_a, knots_b, knots_c = (DATA["q3"]["knots"][x] for x in "abc")
### BEGIN SOLUTION
answer_q3 = [g1_bezier_control_points(D, k) for k in (knots_a, knots_b, knots_c)]
### END SOLUTION
### STUDENT answer_q3 = ...

# %%
check("hw03.q3", answer_q3)

# %% [markdown] solution
# The sketch asked for by Finn: the three splines share all control points except the joints.

# %% solution
### ALT Finn's G1 control points d as grey dots joined by a dotted line, and the three splines
### ALT (a), (b), (c) built from them with different knots, one colour each, their joints marked
### ALT by squares: the curves follow the same control points but bend differently near the joints.
fig, ax = new_figure(figsize=(7, 3.2))
ax.plot(D[:, 0], D[:, 1], "o:", color="0.5", label="G1 control points d")
for label, P, k in zip("abc", answer_q3, (knots_a, knots_b, knots_c), strict=True):
    spline = PiecewiseBezier.from_control_points(P, 3, knots=k)
    pts = spline.evaluate(np.linspace(*spline.domain, 300))
    ax.plot(pts[:, 0], pts[:, 1], label=f"({label}) knots " + ", ".join(f"{v:g}" for v in k))
    ax.plot(P[3::3][:-1, 0], P[3::3][:-1, 1], "s", ms=4, color=ax.lines[-1].get_color())
ax.set_aspect("equal")
ax.legend(fontsize=8)
plt.show()

# %% [markdown]
# ## Question 4 — C1 in the local parameters (multiple choice, feedback only: 0 points)
#
# For which of the knot sequences (a), (b), (c) of question 3 is the spline $C^1$ even in the
# *local* parameters of its segments, i.e. every joint point is the midpoint of its neighbours?
# Answer with the letter(s).

# %%
### BEGIN SOLUTION
# midpoints everywhere <=> equal knot intervals (the barycentric weights are then 1/2)
uniform = [x for x, k in zip("abc", (knots_a, knots_b, knots_c), strict=True) if len(set(np.diff(k))) == 1]
answer_q4 = ", ".join(uniform)
### END SOLUTION
### STUDENT answer_q4 = ...

# %%
check("hw03.q4", answer_q4)

# %% [markdown]
# ## Question 5 — Finn's exercise 19.8.3, numerically (compute)
#
# In the *global* parameter $t$, segment $i$ is the cubic with control points
# $\mathbf p_{3i-3}, \dots, \mathbf p_{3i}$ in the local variable $s = (t - t_{i-1})/(t_i - t_{i-1})$
# (seed 004 §19.7). For the knot sequence of question 3 named in your data, compute the derivative
# $d\mathbf b/dt$ at the joint $t = t_1$ from the left and from the right; answer
# `np.array([left, right])` (shape `(2, 2)`).

# %%
print(DATA["q5"]["text"])  # your data

# %%
### BEGIN SOLUTION
knots_q5 = DATA["q3"]["knots"][DATA["q5"]["letter"]]
P = g1_bezier_control_points(D, knots_q5)
t = np.asarray(knots_q5, dtype=float)
left = 3 * (P[3] - P[2]) / (t[1] - t[0])
right = 3 * (P[4] - P[3]) / (t[2] - t[1])
answer_q5 = np.array([left, right])
# the curve class evaluates in the global parameter (at a joint: the segment starting there)
spline = PiecewiseBezier.from_control_points(P, 3, knots=knots_q5)
assert np.allclose(spline.evaluate(t[1], n=1), right)
### END SOLUTION
### STUDENT answer_q5 = ...

# %%
check("hw03.q5", answer_q5)

# %% [markdown]
# ## Question 6 — Finn's exercise 19.8.3, in general (derive with sympy)
#
# Take one coordinate: symbols `t0, t1, t2` for the knots and `p2, p4` for the neighbours of the
# joint point $p_3$. Build $p_3$ from the knots, then the left derivative at $t_1$ in the global
# parameter, $3(p_3 - p_2)/(t_1 - t_0)$, and simplify it. Answer with the simplified expression.
# Check for yourself that the right derivative $3(p_4 - p_3)/(t_2 - t_1)$ simplifies to the same
# expression: this proves that the $G^1$ spline is $C^1$ in $t$.

# %%
t0, t1, t2, p2, p4 = sp.symbols("t0 t1 t2 p2 p4")
### BEGIN SOLUTION
p3 = ((t2 - t1) * p2 + (t1 - t0) * p4) / (t2 - t0)
answer_q6 = sp.simplify(3 * (p3 - p2) / (t1 - t0))
assert sp.simplify(answer_q6 - 3 * (p4 - p3) / (t2 - t1)) == 0
### END SOLUTION
### STUDENT answer_q6 = ...
answer_q6

# %%
check("hw03.q6", answer_q6)

# %% [markdown]
# ## Question 7 — the knots as shape parameters (write a function)
#
# In the *local* parameters, the two segments at joint $i$ satisfy the first Beta-constraint
# $\mathbf r'(0) = \beta_1 \mathbf q'(1)$. Write `knot_ratio_beta1(knots)` that returns, for
# $L + 1$ knots, the $L - 1$ values of $\beta_1$ at the interior joints $i = 1, \dots, L-1$ as a
# numpy array.
#
# **You may use:** numpy (and plain Python); no function of `course_lib`.
# `course_lib.constructions.knot_splines.knot_ratio_beta1` does it for you, so it raises while your function
# is checked or graded.

# %%
def knot_ratio_beta1(knots):
    """beta1 at each interior joint of Finn's G1 spline with these knots."""
    ### BEGIN SOLUTION
    dt = np.diff(np.asarray(knots, dtype=float))
    return dt[1:] / dt[:-1]
    ### END SOLUTION
    ### STUDENT raise NotImplementedError("write the body of knot_ratio_beta1")

# %%
check("hw03.q7", knot_ratio_beta1)

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
# * in a terminal, from the course folder: `make submit HW=hw03 STUDENT=your-id`
# * in a new cell here: `from course_lib.homework.submit import submit; submit("hw03_g1_knot_bezier_splines.ipynb", student="your-id")`
#
# Either runs the notebook top to bottom in a fresh kernel, as the grader will, lists the cells that
# fail, and writes `submissions/hw03-your-id.ipynb`. Upload that file. The checks above are feedback;
# your grade comes from the grader's own tests, on your data (and, for functions, other data).
