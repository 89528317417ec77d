# Source of exercises/hw04_beta_splines.ipynb and solutions/hw04_beta_splines.ipynb.
# Edit here, then run `python tools/build_homework.py` (format: see that script's docstring).
# ruff: noqa: B018

# %% [markdown]
# *Geometric continuity of parametric curves* · Homework 4 of 5 · after the lecture
# [07 Stitching Bézier curves](../notebooks/07_stitching_bezier_curves.ipynb) and [08 Beta-splines](../notebooks/08_beta_splines.ipynb) (stitching Bézier curves, Beta-splines; seed 000 §8, §10).
#
# # Homework 4 — Stitching Bézier curves and Beta-splines
#
# A Bézier curve of degree $d$ with control points $\mathbf V_0, \dots, \mathbf V_d$ has end
# derivatives $\mathbf q'(1) = d(\mathbf V_d - \mathbf V_{d-1})$ and
# $\mathbf q''(1) = d(d-1)(\mathbf V_{d-2} - 2\mathbf V_{d-1} + \mathbf V_d)$ (seed 000 eq. 8),
# and the same at the start of the next curve $\mathbf W_0, \mathbf W_1, \dots$. Put into the
# Beta-constraints, they tell where $\mathbf W_0, \mathbf W_1, \mathbf W_2$ must go; Beta-splines
# are built from exactly these constructions.
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
# "… is the exercise of hw04.q4: write it yourself" -- and the question earns 0 points. The
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

from course_lib import PiecewiseBezier
from course_lib.homework import variants
from course_lib.homework.checks import check, check_all
from course_lib.plotting import new_figure

HOMEWORK = "hw04"
VARIANT = ""  # paste the code your instructor gave you, e.g. VARIANT = "KQW7MZP3XS"
DATA = variants.data(HOMEWORK, VARIANT)

# %% [markdown]
# ## Question 1 — G1 stitching (compute)
#
# The left curve ends with the control points $\mathbf V_{d-1}$, $\mathbf V_d$ of your data. With
# the $\beta_1$ of your data, where must the second control point $\mathbf W_1$ of the next curve go?

# %%
print(DATA["q1"]["text"])  # your data

# %%
V_dm1, V_d, b1 = np.array(DATA["q1"]["V_dm1"]), np.array(DATA["q1"]["V_d"]), DATA["q1"]["beta1"]
### BEGIN SOLUTION
answer_q1 = V_d + b1 * (V_d - V_dm1)  # seed 000 eq. (9)
### END SOLUTION
### STUDENT answer_q1 = ...

# %%
check("hw04.q1", answer_q1)

# %% [markdown]
# ## Question 2 — G2 stitching (write a function)
#
# Write `g2_stitch(V, beta1, beta2)`: from the control polygon `V` (shape `(d + 1, dim)`,
# $d \ge 2$) of the left curve and the shape parameters, return the first three control points
# $\mathbf W_0, \mathbf W_1, \mathbf W_2$ of the next curve (same degree), shape `(3, dim)`, so
# that the curves meet with $G^2$ continuity with respect to $\beta_1, \beta_2$. Derive
# $\mathbf W_2$ from the second Beta-constraint; it must work for every degree.
#
# **You may use:** numpy (and plain Python); no function of `course_lib`.
# `course_lib.constructions.stitching.g1_stitch_points`, `course_lib.constructions.stitching.g2_stitch_points`,
# `course_lib.constructions.stitching.g2_stitch`, `course_lib.constructions.stitching.gn_stitch_points`,
# `course_lib.constructions.stitching.gn_stitch`, `course_lib.geometry.beta_constraints.apply_beta_constraints`,
# `course_lib.geometry.beta_constraints.beta_coefficients` do it for you, so they raise while your
# function is checked or graded.

# %%
def g2_stitch(V, beta1, beta2):
    """W0, W1, W2 of the next Bézier curve for G2 continuity (seed 000 eq. 9-11)."""
    ### BEGIN SOLUTION
    V = np.asarray(V, dtype=float)
    d = V.shape[0] - 1
    W0 = V[-1]
    W1 = W0 + beta1 * (V[-1] - V[-2])
    W2 = 2 * W1 - W0 + beta1**2 * (V[-3] - 2 * V[-2] + V[-1]) + beta2 * (V[-1] - V[-2]) / (d - 1)
    return np.array([W0, W1, W2])
    ### END SOLUTION
    ### STUDENT raise NotImplementedError("write the body of g2_stitch")

# %%
check("hw04.q2", g2_stitch)

# %% [markdown]
# ## Question 3 — the Farin–Boehm point (compute)
#
# Farin and Boehm build $\mathbf W_2$ geometrically (seed 000 eq. 12): with
# $\gamma = \dfrac{(d-1)(1+\beta_1)}{\beta_2 + \beta_1 (d-1)(1+\beta_1)}$, the point
# $\mathbf T = \mathbf V_{d-1} + \beta_1^2 \gamma (\mathbf V_{d-1} - \mathbf V_{d-2})$, and then
# $\mathbf W_2 = \mathbf W_1 + (\mathbf W_1 - \mathbf T)/\gamma$. For the cubic
# $\mathbf V_0, \dots, \mathbf V_3$ and the $\beta_1$, $\beta_2$ of your data, compute $\mathbf T$.

# %%
print(DATA["q3"]["text"])  # your data

# %%
V_q3 = np.array(DATA["q3"]["V"])
b1, b2 = DATA["q3"]["beta1"], DATA["q3"]["beta2"]
### BEGIN SOLUTION
d = V_q3.shape[0] - 1
gamma = (d - 1) * (1 + b1) / (b2 + b1 * (d - 1) * (1 + b1))
answer_q3 = V_q3[-2] + b1**2 * gamma * (V_q3[-2] - V_q3[-3])
# the geometric construction gives the same W2 as the algebra of question 2:
W1 = V_q3[-1] + b1 * (V_q3[-1] - V_q3[-2])
assert np.allclose(W1 + (W1 - answer_q3) / gamma, g2_stitch(V_q3, b1, b2)[2])
### END SOLUTION
### STUDENT answer_q3 = ...

# %%
check("hw04.q3", answer_q3)

# %% [markdown]
# ## Question 4 — quadratic G1 Beta-splines (write a function)
#
# A quadratic $G^1$ Beta-spline has a control polygon $\mathbf V_0, \dots, \mathbf V_m$ and one
# shape parameter $\beta_{1,j}$ per leg $\mathbf V_j \mathbf V_{j+1}$, $j = 0, \dots, m-1$
# (seed 000 §10.1). Its segment $i = 1, \dots, m-1$ is the quadratic Bézier curve with
# $\mathbf W_{i,1} = \mathbf V_i$ and junction vertices
# $\mathbf W_{i,0} = (\beta_{1,i-1}\mathbf V_{i-1} + \mathbf V_i)/(1 + \beta_{1,i-1})$,
# $\mathbf W_{i,2} = (\beta_{1,i}\mathbf V_i + \mathbf V_{i+1})/(1 + \beta_{1,i})$.
#
# Write `quadratic_beta_spline(V, beta1)` (with `V` of shape `(m + 1, 2)` and `beta1` of shape
# `(m,)`) returning the $m - 1$ Bézier polygons as an array of shape `(m - 1, 3, 2)`.
#
# **You may use:** numpy (and plain Python); no function of `course_lib`.
# `course_lib.constructions.beta_splines.quadratic_cubic.quadratic_beta_spline` does it for you, so it raises while your
# function is checked or graded.

# %%
def quadratic_beta_spline(V, beta1):
    """Bézier control polygons of the quadratic G1 Beta-spline (seed 000 eq. 18-19)."""
    ### BEGIN SOLUTION
    V, b = np.asarray(V, dtype=float), np.asarray(beta1, dtype=float)
    m = V.shape[0] - 1
    polygons = np.empty((m - 1, 3, V.shape[1]))
    for i in range(1, m):
        polygons[i - 1, 0] = (b[i - 1] * V[i - 1] + V[i]) / (1 + b[i - 1])
        polygons[i - 1, 1] = V[i]
        polygons[i - 1, 2] = (b[i] * V[i] + V[i + 1]) / (1 + b[i])
    return polygons
    ### END SOLUTION
    ### STUDENT raise NotImplementedError("write the body of quadratic_beta_spline")

# %%
check("hw04.q4", quadratic_beta_spline)

# %% solution
### ALT A control polygon of five grey points, dotted, and three quadratic Beta-splines over it
### ALT with β1 = 0.5, 1 and 3 at every joint, one colour each: changing β1 changes the shape
### ALT while every curve stays tangent-continuous.
V_demo = np.array([[0, 0], [1, 2], [3, 2.5], [4, 0.5], [6, 1.5]], dtype=float)
fig, ax = new_figure(figsize=(7, 3))
ax.plot(V_demo[:, 0], V_demo[:, 1], "o:", color="0.5", label="control polygon")
for b in (0.5, 1.0, 3.0):
    spline = PiecewiseBezier(list(quadratic_beta_spline(V_demo, np.full(4, b))))
    pts = spline.evaluate(np.linspace(*spline.domain, 300))
    ax.plot(pts[:, 0], pts[:, 1], label=f"β1 = {b} at every joint")
ax.set_aspect("equal")
ax.legend(fontsize=8)
plt.show()

# %% [markdown]
# ## Question 5 — the junction vertex of a cubic G2 Beta-spline (compute)
#
# In the cubic $G^2$ Beta-spline construction (seed 000 §10.2), the junction vertex
# $\mathbf W_{i-1,3} = \mathbf W_{i,0}$ divides the segment from $\mathbf W_{i-1,2}$ to
# $\mathbf W_{i,1}$ in the ratio $1 : \beta_{1,i}$. Compute it for the
# $\mathbf W_{i-1,2}$, $\mathbf W_{i,1}$ and $\beta_{1,i}$ of your data.

# %%
print(DATA["q5"]["text"])  # your data

# %%
W_left, W_right = np.array(DATA["q5"]["W_left"]), np.array(DATA["q5"]["W_right"])
b1 = DATA["q5"]["beta1"]
### BEGIN SOLUTION
answer_q5 = (b1 * W_left + W_right) / (1 + b1)
# G1 at the junction: 3 (W_right - J) = beta1 * 3 (J - W_left)
assert np.allclose(W_right - answer_q5, b1 * (answer_q5 - W_left))
### END SOLUTION
### STUDENT answer_q5 = ...

# %%
check("hw04.q5", answer_q5)

# %% [markdown]
# ## Question 6 — the special values (multiple choice, feedback only: 0 points)
#
# With $\beta_1 = 1$ and $\beta_2 = 0$ at every joint, what is the cubic $G^2$ Beta-spline? Which
# one of the four statements of your data (in your own order) is true? Answer with one letter.
# The check tells you whether you are right; this question earns no points.

# %%
print(DATA["q6"]["text"])  # your data

# %%
### BEGIN SOLUTION
# β1 = 1, β2 = 0: γ = 1, and the junction vertices are the B-spline's (see below)
right = "the uniform cubic B-spline of the same control polygon"
answer_q6 = "".join(x for x, label in DATA["q6"]["options"].items() if label == right)
### END SOLUTION
### STUDENT answer_q6 = ...

# %%
check("hw04.q6", answer_q6)

# %% [markdown] solution
# With $\beta_1 = 1$, $\beta_2 = 0$: $\gamma = 1$, the interior vertices trisect each leg and the
# junction vertex is $(\mathbf V_{i-1} + 4\mathbf V_i + \mathbf V_{i+1})/6$ — the Bézier points of
# the uniform cubic B-spline. The Beta-constraints reduce to $C^2$.

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
# * in a terminal, from the course folder: `make submit HW=hw04 STUDENT=your-id`
# * in a new cell here: `from course_lib.homework.submit import submit; submit("hw04_beta_splines.ipynb", student="your-id")`
#
# Either runs the notebook top to bottom in a fresh kernel, as the grader will, lists the cells that
# fail, and writes `submissions/hw04-your-id.ipynb`. Upload that file. The checks above are feedback;
# your grade comes from the grader's own tests, on your data (and, for functions, other data).
