"""The homework boundary: everything between a student's notebook and the grade.

* :mod:`~course_lib.homework.checks` -- the feedback checks, one module per homework with its
  variant generator (``hwNN.py``), and the lectures' practice questions (``lectures.py``);
* :mod:`~course_lib.homework.answers` -- the answer readers shared by the checks and the
  hidden tests;
* :mod:`~course_lib.homework.protocol` -- the wire format between a student's kernel and the
  grader (public: ``tools/grading`` depends on it);
* :mod:`~course_lib.homework.variants` -- every student their own data, from a code;
* :mod:`~course_lib.homework.own_work` -- the guard that makes a library call that solves an
  exercise cost the question;
* :mod:`~course_lib.homework.submit` -- the hand-in from the notebook.

Importing this package imports none of them.
"""
