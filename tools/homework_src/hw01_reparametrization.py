# Source of exercises/hw01_reparametrization.ipynb and solutions/hw01_reparametrization.ipynb.
# Edit here, then run `python tools/build_homework.py` (format: see that script's docstring).
# ruff: noqa: B018

# %% [markdown]
# *Geometric continuity of parametric curves* · Homework 1 of 5 · after the lecture
# [01 Parametric continuity](../notebooks/01_parametric_continuity.ipynb) and [02 Reparametrization](../notebooks/02_reparametrization.ipynb) (seed 000 §1–4, seed 004 §19.2).
#
# # Homework 1 — Parametrizations, the unit tangent and reparametrization
#
# A curve is a set of points; a *parametrization* is one way of tracing it. In this homework you
# compute the first "geometric" derivative (the unit tangent), apply the chain rule to a change of
# variables, and sort the quantities that belong to the curve from those that belong to one
# parametrization only.
#
# **How to work.** Replace each `...` by your answer (or write the body of the function), run the
# cell, then run the **check cell** below it:
#
# - ✓ your answer has the properties it must have;
# - ✗ what is wrong, in the terms of the course;
# - … not answered yet.
# - ? (q1, q4, q5, q7) the form is right, but this copy of the course has no answer key for
#   your data: only the grader checks the value. Check `VARIANT`; if it is right, tell your
#   instructor.
#
# The checks are feedback, not the grade: the grade comes from the grader's own tests, on your
# data and, for the functions, on other data too, so write code that works in general. Keep
# the names (`answer_q1`, `chain_rule_derivatives`, ...),
# do not delete cells, and before you hand in run *Kernel → Restart Kernel and Run All Cells*.
# Numbers are checked and graded to about 9 decimals (q7, an integral: 6 significant digits):
# compute them in Python from `DATA`; a rounded number you type in is wrong.
# Multiple-choice questions are for practice, worth 0 points: a letter can be found by trying
# each one in its check.
#
# **Your own work.** Points are for what you write yourself. A function you write must not call
# the `course_lib` function that already does it (each function question says what you may
# use): while your function is checked or graded, those library functions raise an error --
# "… is the exercise of hw01.q2: write it yourself" -- and the question earns 0 points. The
# checks do not hand out answers either: they say ✓ or ✗, and what kind of case went wrong.
# The checks of q1, q4, q5 and q7 do not even know the value: they compare a fingerprint of
# your answer with one your instructor made from the grader's tests.
#
# **Your own data.** Every student gets their own numbers: paste the *variant code* your
# instructor gave you into `VARIANT` below. The cells marked "your data" print the data of each
# question; your code should use `DATA[...]` rather than typing the numbers. With `VARIANT = ""`
# you get the example data (fine for practice, but graded on your own data it scores nothing).

# %% [markdown]
# ## Preparations

# %%
import numpy as np
import sympy as sp
from numpy.polynomial import polynomial as P
from scipy.integrate import quad

from course_lib.homework import variants
from course_lib.homework.checks import check, check_all

HOMEWORK = "hw01"
VARIANT = ""  # paste the code your instructor gave you, e.g. VARIANT = "KQW7MZP3XS"
DATA = variants.data(HOMEWORK, VARIANT)

# %% [markdown]
# ## Question 1 — a unit tangent (compute)
#
# The plane curve $\mathbf c(t) = (x(t), y(t))$ of your data (printed below) is traced for
# increasing $t$. Compute its unit tangent $\mathbf T(t_0) = \mathbf c'(t_0) / \lVert \mathbf
# c'(t_0) \rVert$ at the point $t_0$ of your data (seed 004 §19.2) as a numpy array of shape
# `(2,)`. `DATA["q1"]` also holds the coefficients of $x$ and $y$ in ascending powers of $t$
# (for `numpy.polynomial.polynomial`, imported as `P`) and `t`.

# %%
print(DATA["q1"]["text"])  # your data

# %%
### BEGIN SOLUTION
d = DATA["q1"]
c1 = np.array([P.polyval(d["t"], P.polyder(d["x"])), P.polyval(d["t"], P.polyder(d["y"]))])
answer_q1 = c1 / np.linalg.norm(c1)
### END SOLUTION
### STUDENT answer_q1 = ...

# %%
check("hw01.q1", answer_q1)

# %% [markdown]
# ## Question 2 — the chain rule (write a function)
#
# Let $\tilde{\mathbf q}(s) = \mathbf q(f(s))$. Write `chain_rule_derivatives(q1, q2, f1, f2)`
# that returns the array `[q̃'(s), q̃''(s)]` (shape `(2, dim)`) from
#
# - `q1`, `q2`: the vectors $\mathbf q'(f(s))$ and $\mathbf q''(f(s))$ (numpy arrays of shape `(dim,)`),
# - `f1`, `f2`: the numbers $f'(s)$ and $f''(s)$.
#
# It must work in the plane and in space.
#
# **You may use:** numpy (and plain Python); no function of `course_lib`.
# `course_lib.geometry.reparametrization.faa_di_bruno`, `course_lib.geometry.chain_rule.compose_derivatives`,
# `course_lib.geometry.beta_constraints.apply_beta_constraints`,
# `course_lib.geometry.beta_constraints.beta_coefficients` do it for you, so they raise while your
# function is checked or graded.

# %%
def chain_rule_derivatives(q1, q2, f1, f2):
    """First and second derivative of q(f(s)), stacked as an array of shape (2, dim)."""
    ### BEGIN SOLUTION
    q1, q2 = np.asarray(q1, dtype=float), np.asarray(q2, dtype=float)
    return np.array([q1 * f1, q2 * f1**2 + q1 * f2])
    ### END SOLUTION
    ### STUDENT raise NotImplementedError("write the body of chain_rule_derivatives")

# %%
check("hw01.q2", chain_rule_derivatives)

# %% [markdown]
# ## Question 3 — which is a change of variables? (multiple choice, feedback only: 0 points)
#
# Seed 000 §4 asks of an *orientation-preserving change of variables* $f$ from $[0, 1]$ onto
# $[0, 1]$: it is regular and $C^n$, it maps the interval **onto** the interval, and $f' > 0$.
# Which one of the four options of your data qualifies?
#
# Answer with a letter, e.g. `answer_q3 = "a"`.

# %%
print(DATA["q3"]["text"])  # your data

# %%
### BEGIN SOLUTION
s_ = sp.Symbol("s")


def qualifies(coef):  # f(0) = 0, f(1) = 1, and f' > 0 on [0, 1]
    f = sum(c * s_**i for i, c in enumerate(map(sp.nsimplify, coef)))
    ends = f.subs(s_, 0) == 0 and f.subs(s_, 1) == 1
    return ends and sp.minimum(f.diff(s_), s_, sp.Interval(0, 1)) > 0


answer_q3 = "".join(x for x, coef in DATA["q3"]["coefficients"].items() if qualifies(coef))
### END SOLUTION
### STUDENT answer_q3 = ...

# %%
check("hw01.q3", answer_q3)

# %% [markdown] solution
# With the example data: (a) $s^2$ has $f'(0) = 0$: not regular at $s = 0$. (b) $1 - s$ has
# $f' = -1 < 0$: it reverses the orientation. (c) $2s$ maps $[0, 1]$ onto $[0, 2]$. (d) has
# $f(0) = 0$, $f(1) = 1$ and $f'(s) = (1 + 2s)/2 > 0$. Every variant has one option of each kind.

# %% [markdown]
# ## Question 4 — a signed curvature (derive with sympy)
#
# For the parabola $\mathbf q(u) = (u, k u^2)$ of your data, use sympy to compute the signed
# curvature $\kappa = \det(\mathbf q', \mathbf q'') / \lVert \mathbf q' \rVert^3$ (seed 004 §19.2:
# positive when the curve turns towards $\mathbf N$, i.e. to the left) at the point $u_0$ of your
# data (`DATA["q4"]["k"]`, `DATA["q4"]["u"]`). An exact sympy number or a float are both fine.

# %%
print(DATA["q4"]["text"])  # your data

# %%
### BEGIN SOLUTION
u = sp.Symbol("u", real=True)
k = sp.nsimplify(DATA["q4"]["k"])
q = sp.Matrix([u, k * u**2])
dq, ddq = q.diff(u), q.diff(u, 2)
kappa = (dq[0] * ddq[1] - dq[1] * ddq[0]) / dq.dot(dq) ** sp.Rational(3, 2)
answer_q4 = sp.simplify(kappa.subs(u, sp.nsimplify(DATA["q4"]["u"])))
### END SOLUTION
### STUDENT answer_q4 = ...
answer_q4

# %%
check("hw01.q4", answer_q4)

# %% [markdown]
# ## Question 5 — reparametrize the parabola (compute)
#
# Reparametrize the parabola $\mathbf q(u) = (u, k u^2)$ of question 4 by the change of
# variables $f$ of your data (a change of variables as in question 3): $\tilde{\mathbf q}(s) =
# \mathbf q(f(s))$. Compute $\tilde{\mathbf q}''(s_0)$ at the point $s_0$ of your data (shape
# `(2,)`), for instance with your `chain_rule_derivatives`. `DATA["q5"]` holds `k`, the
# coefficients `f` of $f$ in ascending powers of $s$, and `s`.

# %%
print(DATA["q5"]["text"])  # your data

# %%
### BEGIN SOLUTION
d = DATA["q5"]
s, k, fc = d["s"], d["k"], d["f"]
f, f1, f2 = P.polyval(s, fc), P.polyval(s, P.polyder(fc)), P.polyval(s, P.polyder(fc, 2))
answer_q5 = chain_rule_derivatives(np.array([1.0, 2 * k * f]), np.array([0.0, 2 * k]), f1, f2)[1]
# the same by differentiating q(f(s)) directly with sympy:
s_ = sp.Symbol("s")
fs = sum(c * s_**i for i, c in enumerate(map(sp.nsimplify, fc)))
direct = sp.Matrix([fs, sp.nsimplify(k) * fs**2]).diff(s_, 2).subs(s_, sp.nsimplify(s))
assert np.allclose(answer_q5, np.array(direct, dtype=float).ravel())
### END SOLUTION
### STUDENT answer_q5 = ...

# %%
check("hw01.q5", answer_q5)

# %% [markdown]
# ## Question 6 — what belongs to the curve? (multiple choice, several answers; feedback only: 0 points)
#
# Which of these quantities are *intrinsic* — the same for every equivalent parametrization at the
# same point of the curve (seed 000 §4)? The options are in your data, in your own order.
#
# Answer with all right letters, e.g. `answer_q6 = "a, c"`.

# %%
print(DATA["q6"]["text"])  # your data

# %%
### BEGIN SOLUTION
intrinsic = {"the unit tangent vector", "the curvature vector"}
answer_q6 = ", ".join(x for x, label in DATA["q6"]["options"].items() if label in intrinsic)
### END SOLUTION
### STUDENT answer_q6 = ...

# %%
check("hw01.q6", answer_q6)

# %% [markdown] solution
# By the chain rule $\tilde{\mathbf q}' = \mathbf q' f'$ changes with $f'$, and so does the speed;
# $\tilde{\mathbf q}'' = \mathbf q'' f'^2 + \mathbf q' f''$ changes too. The unit tangent and the
# curvature vector are derivatives with respect to arc length, which does not depend on $f$.

# %% [markdown]
# ## Question 7 — an arc length (compute)
#
# Compute the length of the parabola $\mathbf q(u) = (u, k u^2)$, $0 \le u \le b$, of your data
# (`DATA["q7"]["k"]`, `DATA["q7"]["b"]`): the integral of the speed $\lVert \mathbf q'(u)
# \rVert$ (seed 004 §19.2). A numerical integral is fine.

# %%
print(DATA["q7"]["text"])  # your data

# %%
### BEGIN SOLUTION
k, b = DATA["q7"]["k"], DATA["q7"]["b"]
answer_q7, _error = quad(lambda u: np.hypot(1.0, 2.0 * k * u), 0.0, b)
### END SOLUTION
### STUDENT answer_q7 = ...

# %%
check("hw01.q7", answer_q7)

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
# * in a terminal, from the course folder: `make submit HW=hw01 STUDENT=your-id`
# * in a new cell here: `from course_lib.homework.submit import submit; submit("hw01_reparametrization.ipynb", student="your-id")`
#
# Either runs the notebook top to bottom in a fresh kernel, as the grader will, lists the cells that
# fail, and writes `submissions/hw01-your-id.ipynb`. Upload that file. The checks above are feedback;
# your grade comes from the grader's own tests, on your data (and, for functions, other data).
