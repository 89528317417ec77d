"""The grader: hidden tests run here; student code runs in a sandbox (see grade.py)."""
