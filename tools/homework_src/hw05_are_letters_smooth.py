# Source of exercises/hw05_are_letters_smooth.ipynb and solutions/hw05_are_letters_smooth.ipynb.
# Edit here, then run `python tools/build_homework.py` (format: see that script's docstring).
# ruff: noqa: B018

# %% [markdown]
# *Geometric continuity of parametric curves* · Homework 5 of 5 · after the lecture
# [11 Are letters smooth?](../notebooks/11_are_letters_smooth.ipynb) (TrueType outlines, implied
# points, curvature combs; Beta-splines of seed 000 §10.1–10.2).
#
# # Homework 5 — Are letters smooth?
#
# The lecture measured the S, O, g and @ of DejaVu Sans. Here you take a letter the lecture did
# not show, a lower-case letter with a **bowl** and a **stem** (the b of DejaVu Sans in the
# example data; a b, d, p or q of DejaVu Sans, Sans Bold, Sans Mono or Sans Mono Bold in yours):
# classify every joint of its outline, compute the curvature jump at one implied point by hand,
# write the G2 test of an implied point, and then make the outer contour of your glyph G2
# **while keeping its corners** — the stem must stay a stem.
#
# **How to work.** Replace each `...` by your answer (or write the body of the function), run the
# cell, then run the **check cell** below it:
#
# - ✓ your answer has the properties it must have;
# - ✗ what is wrong, in the terms of the course;
# - … not answered yet.
#
# The checks are feedback, not the grade: the grade comes from the grader's own tests, on your data
# and, for the functions, on other data (other points, other glyphs), so write code that works in
# general. Keep the names (`answer_q1`, `implied_is_g2`, ...), do not delete cells, and before you
# hand in run *Kernel → Restart Kernel and Run All Cells*. Multiple-choice questions are for
# practice, worth 0 points: a letter can be found by trying each one in its check.
#
# **Your own work.** Points are for what you write yourself. A function you write must not call
# the `course_lib` function that already does it (each function question says what you may
# use): while your function is checked or graded, those library functions raise an error --
# "… is the exercise of hw05.q5: write it yourself" -- and the question earns 0 points. The
# checks do not hand out answers either: they say ✓ or ✗, and what kind of case went wrong.
#
# **Your own data.** Every student gets their own glyph, point and option order: paste the
# *variant code* your instructor gave you into `VARIANT` below. The cells marked "your data" print
# the data of each question; your code should use `DATA[...]` rather than typing the numbers. With
# `VARIANT = ""` you get the example data, the b of DejaVu Sans (fine for practice, but graded on
# your own data it scores nothing).

# %% [markdown]
# ## Preparations

# %%
import matplotlib.pyplot as plt
import numpy as np

from course_lib import PiecewiseBezier
from course_lib.constructions.beta_splines import cubic_beta_spline
from course_lib.constructions.outlines import (
    Contour,
    Outline,
    classify_joints,
    glyph_outline,
    glyph_summary,
)
from course_lib.homework import variants
from course_lib.homework.checks import check, check_all
from course_lib.plotting import plot_outline

HOMEWORK = "hw05"
VARIANT = ""  # paste the code your instructor gave you, e.g. VARIANT = "KQW7MZP3XS"
DATA = variants.data(HOMEWORK, VARIANT)

# your glyph, coordinates in em (font units / units per em)
glyph = glyph_outline(DATA["glyph"]["char"], DATA["glyph"]["font"])
print(DATA["glyph"]["text"])  # your data

# %% [markdown]
# ## Question 1 — classify the joints of your glyph (compute; practice: 0 points)
#
# Your glyph has two contours: the outer one (stem and bowl) and the counter inside the bowl. With
# the lecture's tolerances (the defaults of `classify_joints`: a **corner** where the tangent
# turns by more than 2°; otherwise a smooth point, **G2** if the curvature jump relative to the
# local curvature is at most $10^{-8}$, else **G1**), count the joints of the whole glyph, the
# closing joint of each contour included. Give `answer_q1` as three integers
# `[corners, G1 smooth points that are not G2, G2 smooth points]`.

# %%
### BEGIN SOLUTION
counts = classify_joints(glyph).counts()
answer_q1 = np.array([counts["corner"], counts["G1"], counts["G2"]])
assert counts["gap"] == counts["singular"] == 0
### END SOLUTION
### STUDENT answer_q1 = ...

# %%
check("hw05.q1", answer_q1)

# %% [markdown]
# ## Question 2 — the G2 test of an implied point (write a function)
#
# Two quadratic segments $P_0, A, M$ and $M, B, P_2$ meet at the implied point $M = (A + B)/2$.
# The lecture computed that they are always G1 there, and that the numerator of their
# curvature jump is $2\,(B - A) \times (P_2 - P_0)$.
#
# Write `implied_is_g2(P0, A, B, P2)` (four plane points) returning `True` when the two segments
# are G2 at $M$ and `False` otherwise. Floating-point data is never exactly parallel, and
# coordinates may be in font units (thousands) or in em (fractions): decide with a **relative**
# test, G2 when $|(B - A) \times (P_2 - P_0)| \le 10^{-9}\,|B - A|\,|P_2 - P_0|$. You may
# assume $A \ne B$ and $P_0 \ne P_2$.
#
# **You may use:** numpy (and plain Python); no function of `course_lib`.
# `course_lib.constructions.outlines.classification.classify_joints`, `course_lib.geometry.continuity.joint_continuity`,
# `course_lib.geometry.continuity.curve_continuity` do it for you, so they raise while your function is
# checked or graded.

# %%
def implied_is_g2(P0, A, B, P2):
    """True when the quadratics P0, A, M and M, B, P2 (M = (A + B)/2) are G2 at M."""
    ### BEGIN SOLUTION
    leg = np.asarray(B, dtype=float) - np.asarray(A, dtype=float)
    chord = np.asarray(P2, dtype=float) - np.asarray(P0, dtype=float)
    cross = leg[0] * chord[1] - leg[1] * chord[0]
    return bool(abs(cross) <= 1e-9 * np.linalg.norm(leg) * np.linalg.norm(chord))
    ### END SOLUTION
    ### STUDENT raise NotImplementedError("write the body of implied_is_g2")

# %%
check("hw05.q2", implied_is_g2)

# %% [markdown]
# ## Question 3 — the curvature jump at one implied point (compute; practice: 0 points)
#
# On the bowl of your glyph, the outer contour has four consecutive stored points (font units,
# printed below): $P_0$ (on-curve), $A$, $B$ (off-curve) and the next on-curve point $P_2$; between
# $A$ and $B$ lies the implied point $M$ (in the example data, at the top left of the bowl of the
# b: $P_0 = (371, 950)$, $A = (429, 1050)$, $B = (606, 1147)$, $P_2 = (729, 1147)$). Compute,
# **in em** (divide the coordinates by the units per em, `DATA["q3"]["em"]`, first), the signed
# curvature $\kappa = (\mathbf x' \times \mathbf x'')/|\mathbf x'|^3$ at $M$ on both sides: at the
# end of the segment $P_0, A, M$ and at the start of $M, B, P_2$.
# `answer_q3 = [kappa_in, kappa_out]`.

# %%
print(DATA["q3"]["text"])  # your data

# %%
pts_q3 = np.array(DATA["q3"]["points"]) / DATA["q3"]["em"]  # P0, A, B, P2 in em
### BEGIN SOLUTION
P0, A, B, P2 = pts_q3
M = (A + B) / 2


def signed_curvature(d1, d2):
    return (d1[0] * d2[1] - d1[1] * d2[0]) / np.linalg.norm(d1) ** 3


# end derivatives of a quadratic Bézier curve (seed 000 eq. 8 with d = 2)
kappa_in = signed_curvature(2 * (M - A), 2 * (P0 - 2 * A + M))
kappa_out = signed_curvature(2 * (B - M), 2 * (M - 2 * B + P2))
answer_q3 = np.array([kappa_in, kappa_out])
# the same as classify_joints: the joint of the outer contour at M
t = classify_joints(glyph)
k = np.flatnonzero(np.all(np.isclose(t.point, M, rtol=0, atol=1e-12), axis=1))[0]
assert np.allclose(answer_q3, [t.kappa_in[k], t.kappa_out[k]]) and not implied_is_g2(P0, A, B, P2)
### END SOLUTION
### STUDENT answer_q3 = ...

# %%
check("hw05.q3", answer_q3)

# %% [markdown]
# ## Question 4 — where is your glyph G2? (multiple choice, feedback only: 0 points)
#
# Question 1 found a few G2 smooth points on your glyph. Look at where they are
# (`classify_joints(glyph).point[classify_joints(glyph).kind == "G2"]`) and at the points around
# them. Why are they G2? The cell below prints four reasons (a)–(d), in your own order; answer
# with the letter of the right one. (Multiple choice is feedback only in this course: `check()`
# tells you whether your letter is right, and the question earns no points.)

# %%
print(DATA["q4"]["text"])  # your data

# %%
### BEGIN SOLUTION
# the reason that holds: the chord P0P2 is parallel to the leg AB at every G2 point
(answer_q4,) = [x for x, text in DATA["q4"]["options"].items() if text.startswith("at each of them the chord")]
### END SOLUTION
### STUDENT answer_q4 = ...

# %%
check("hw05.q4", answer_q4)

# %% [markdown] solution
# The G2 points are extremes of the counter or of the bowl (in the b of DejaVu Sans: the four
# extremes of the counter and the rightmost point of the bowl): the on-curve point is stored,
# but it sits exactly at the midpoint of its off-curve neighbours $A$, $B$, and the leg $AB$ and
# the chord $P_0P_2$ are both horizontal (or both vertical), so $(B - A) \times (P_2 - P_0) = 0$.
# The other stored smooth points (in the b, the top and bottom of the bowl, whose left end meets
# the stem) are not at such a level place: they are only G1. Reason (a) is false (explicit G1
# points exist), (c) too (every smooth point turns by less than 2°), and (d) (the curvature at a
# G2 point of a bowl is not zero).

# %% [markdown]
# ## Question 5 — a G2 run between two corners (write a function)
#
# The lecture made the O G2 with the cubic Beta-spline with $\beta_1 = 1$, $\beta_2 = 0$ (the
# uniform cubic B-spline) on its closed off-curve polygon. A contour with corners needs an
# *open* version that keeps each corner where it is and keeps the tangent directions there, so
# that a corner stays the same corner. Between two corners $V_0$ and $V_n$, take the **run
# polygon** $V_0, V_1, \dots, V_n$ (the corners at the ends, the control points in between) and
# add a **phantom vertex** at each end, the reflection of the neighbour through the corner:
#
# $$V_{-1} = 2V_0 - V_1, \qquad V_{n+1} = 2V_n - V_{n-1}.$$
#
# The uniform cubic B-spline on $V_{-1}, V_0, \dots, V_{n+1}$ then starts at
# $(V_{-1} + 4V_0 + V_1)/6 = V_0$ with the tangent direction $V_1 - V_0$, ends at $V_n$ with the
# direction $V_n - V_{n-1}$, and is G2 (even $C^2$) at all its joints.
#
# Write `g2_run(V)`: from a run polygon `V` of shape `(n + 1, 2)`, $n \ge 1$, return the Bézier
# control points of that B-spline's $n$ cubic segments, an array of shape `(n, 4, 2)`, in the
# order from $V_0$ to $V_n$ (`cubic_beta_spline(points, 1.0, 0.0)` builds the B-spline; its
# `.segments` are the Bézier polygons).
#
# **You may use:** numpy and `course_lib.constructions.beta_splines.cubic_beta_spline` (the B-spline itself);
# the phantom vertices are the exercise.

# %%
def g2_run(V):
    """Bézier polygons (n, 4, 2) of the uniform cubic B-spline on V with phantom end vertices."""
    ### BEGIN SOLUTION
    V = np.asarray(V, dtype=float)
    extended = np.vstack([2 * V[0] - V[1], V, 2 * V[-1] - V[-2]])
    return np.array(cubic_beta_spline(extended, 1.0, 0.0).segments)
    ### END SOLUTION
    ### STUDENT raise NotImplementedError("write the body of g2_run")

# %%
check("hw05.q5", g2_run)

# %% [markdown]
# ## Question 6 — your glyph made G2, corners kept (compute; practice: 0 points)
#
# The outer contour of your glyph runs round the bowl from the corner where the bowl leaves the
# stem to the corner where it meets the stem again, then along straight lines round the stem
# back to the start. Your data gives the stored point indices (`glyph.points[c]` holds the
# stored points and on-curve flags of contour `c`): `DATA["q6"]["bowl"]`, the bowl from corner
# to corner (in the b of the example data: 0, 1, ..., 12), and `DATA["q6"]["stem"]`, the stem
# from that corner back to the first one (in the b: 12 → 13 → 14 → 15 → 16 → 0). The cell
# below gives the run polygon of the bowl: its stored points without the on-curve points that
# sit between two off-curve points (they lie on the legs of the polygon, as in the lecture's O).
#
# Replace the bowl by `g2_run(V_bowl)` and keep the straight lines of the stem; keep the counter
# (contour `DATA["q6"]["counter"]`) as it is. Build the new glyph as an `Outline` of two closed
# contours, `Outline((counter, Contour(curve, True, flags)), "name")` with
# `flags = np.zeros(curve.n_segments, bool)` (a closed contour has one joint per segment, none of
# them implied now), and classify its joints as in question 1:
# `answer_q6 = [corners, G1 not G2, G2]`.

# %%
print(DATA["q6"]["text"])  # your data

# %%
P_outer, on_outer = glyph.points[DATA["q6"]["outer"]]
bowl, stem = DATA["q6"]["bowl"], DATA["q6"]["stem"]  # stored point indices
P_bowl, on_bowl = P_outer[bowl], on_outer[bowl]
between_off = on_bowl[1:-1] & ~on_bowl[:-2] & ~on_bowl[2:]
V_bowl = P_bowl[np.concatenate([[True], ~between_off, [True]])]
len(P_outer), V_bowl.shape

# %%
### BEGIN SOLUTION
lines = [P_outer[[stem[k], stem[k + 1]]] for k in range(len(stem) - 1)]  # straight lines
outer = PiecewiseBezier(list(g2_run(V_bowl)) + lines)
counter = glyph.contours[DATA["q6"]["counter"]]
glyph_g2 = Outline((counter, Contour(outer, True, np.zeros(outer.n_segments, bool))), f"{glyph.name}, bowl G2")
counts = classify_joints(glyph_g2).counts()
answer_q6 = np.array([counts["corner"], counts["G1"], counts["G2"]])
# the corners are the same points with the same angles
t_old, t_new = classify_joints(glyph), classify_joints(glyph_g2)
old, new = t_old.kind == "corner", t_new.kind == "corner"
assert np.allclose(sorted(t_old.angle[old]), sorted(t_new.angle[new]), rtol=0, atol=1e-9)
assert np.allclose(np.sort(t_old.point[old], axis=0), np.sort(t_new.point[new], axis=0))
### END SOLUTION
### STUDENT answer_q6 = ...

# %%
check("hw05.q6", answer_q6)

# %% solution
### ALT Two outlines of the same glyph side by side, each with its curvature comb and its joints
### ALT marked by kind (corner, G1, G2); the title of each gives how many of its points are G2:
### ALT the repaired outline on the right has more.
fig, axes = plt.subplots(1, 2, figsize=(7.9, 4.6))
for ax, outline in zip(axes, (glyph, glyph_g2), strict=True):
    plot_outline(ax, outline, comb_scale=0.01, teeth_per_segment=25, legend=(outline is glyph_g2))
    ax.set_title(f"{outline.name}: {glyph_summary(outline).g2} G2 points")
plt.show()

# %% [markdown] solution
# Left, the glyph: the comb of the bowl steps at every purple point. Right, the bowl rebuilt
# with `g2_run`: the comb runs on through every joint of the bowl, the corners are where they
# were with the same angles, and the curvature falls to zero at the two corners (the phantom
# vertices make $V_{-1} - 2V_0 + V_1 = 0$). The price, as in the lecture: the bowl no longer passes
# through the font's on-curve points.

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
# * in a terminal, from the course folder: `make submit HW=hw05 STUDENT=your-id`
# * in a new cell here: `from course_lib.homework.submit import submit; submit("hw05_are_letters_smooth.ipynb", student="your-id")`
#
# Either runs the notebook top to bottom in a fresh kernel, as the grader will, lists the cells that
# fail, and writes `submissions/hw05-your-id.ipynb`. Upload that file. The checks above are feedback;
# your grade comes from the grader's own tests, on your data (and, for functions, other data).
