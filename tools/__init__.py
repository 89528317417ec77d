"""The course's tools: homework builder, grader, variant codes, site, handouts, release.

``tools`` is a package installed (editable) with the course by ``make install``, so its modules
import as ``tools.grading``, ``tools.build_homework``, ... from anywhere in the course's
environment (tests included).  Each ``tools/<name>.py`` is also the command the README prints
(``tools/grade.py ...``, ``.venv/bin/python tools/build_homework.py``): run as a script it
imports its siblings through the package, never through ``sys.path``.
"""
