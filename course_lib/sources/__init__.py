"""The sources' formulas as printed, next to the corrected ones.

:mod:`~course_lib.sources.seed_formulas` keeps each formula of the course's sources in the
form the source prints it, so a lecture can show it failing beside the corrected form (the
README's "Errors in the sources").  Nothing else in the package uses these forms.
"""
