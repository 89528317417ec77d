"""The tools of each lecture, gathered so that a lecture opens with one short import cell.

``from course_lib.lessons.l05 import *`` brings in what lecture 05 uses; each module lists
where every name comes from (the modules of ``course_lib`` that define and document it).
Nothing here defines mathematics: these modules only re-export.
"""
