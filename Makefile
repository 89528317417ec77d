# The course's commands.  On a fresh machine (Python 3.10+):
#   make lab    create .venv, install the course, open JupyterLab on notebooks/00_welcome.ipynb
#   make test   create .venv, install the course, run the whole test suite
#   make present L=04   the lecture as projector slides with live demos (Voila, see site/teaching.md)
#   make bench  print the benchmark table;  make grade  grade a folder of homework (see site/grading.md)
#   make site   the course as a static website in build/site/ (index.html; any static host)
#   make handouts  one PDF per lecture in build/handouts/ (needs Debian's chromium)
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
# JupyterLab refuses to run as root without this flag (containers, CI machines)
ALLOW_ROOT := $(if $(filter 0,$(shell id -u)),--allow-root,)

.PHONY: install lab present test lint bench grade submit release site handouts clean

$(STAMP): pyproject.toml constraints.txt
	@echo "installing the course into $(VENV) (4-6 minutes the first time; pip shows its progress)"
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --progress-bar on -c constraints.txt -e ".[test]"
	touch $@

install: $(STAMP)

# the course's own JupyterLab settings and save hook (never the user's ~/.jupyter)
LAB_CONFIG := $(CURDIR)/.jupyter-course/jupyter_server_config.py
lab: install
	$(BIN)/jupyter lab --config=$(LAB_CONFIG) --ServerApp.root_dir=$(CURDIR) $(ALLOW_ROOT) notebooks/00_welcome.ipynb

# make present L=04 [PORT=8866]: a deck generated from the lecture, served by Voila
L ?= 00
PORT ?= 8866
present: install
	$(BIN)/python tools/present.py $(L) --port $(PORT)

test: install
	@bash tools/ensure-browser || true
	@bash tools/ensure-sandbox || true
	@bash tools/ensure-test-data || true
	$(BIN)/ruff check course_lib tests benchmarks tools conftest.py solutions/hidden_tests
	$(BIN)/python -m pytest -n 2 --dist loadfile --no-loadscope-reorder

lint: install
	$(BIN)/ruff check course_lib tests benchmarks tools conftest.py solutions/hidden_tests

bench: install
	$(BIN)/python benchmarks/run.py

# make grade HW=hw01 SUBMISSIONS=path/to/submitted/notebooks OUT=grades/hw01
#      [ROSTER=roster.csv] [SECRET=course_secret.txt] [FORMAT=plain|canvas|moodle]
#      [DEADLINE=2026-12-08T23:59+01:00] [PENALTY=10%] [EXECUTOR=local|dask] [ONLY=student]
#      [ASSIGNMENT="Homework 1"]  (the Canvas export's column to fill, with or without its "(id)")
HW ?= hw01
# HW=hw3, HW=3, HW=hw03 or HW=hw03_name all name hw03, as `make submit HW=...` reads them
# (course_lib.submit.find_homework); anything else is passed on as written, for grade.py to refuse
HW_ID := $(shell n=$$(printf '%s' '$(HW)' | sed -E 's/_.*//; s/^[Hh][Ww]//; s/^0+//'); \
	case "$$n" in ([1-9]|[1-9][0-9]) printf 'hw%02d' "$$n";; (*) printf '%s' '$(HW)';; esac)
OUT ?= grading-output/$(HW_ID)
GRADE_OPTS = $(if $(ROSTER),--roster "$(ROSTER)") $(if $(SECRET),--secret-file "$(SECRET)") \
	$(if $(FORMAT),--format $(FORMAT)) $(if $(DEADLINE),--deadline "$(DEADLINE)") \
	$(if $(PENALTY),--late-penalty "$(PENALTY)") $(if $(EXECUTOR),--executor $(EXECUTOR)) \
	$(if $(ONLY),--only "$(ONLY)") $(if $(ASSIGNMENT),--assignment "$(ASSIGNMENT)")
grade: install
	@bash tools/ensure-sandbox || true
	@test -n "$(SUBMISSIONS)" || (echo "usage: make grade HW=hw01 SUBMISSIONS=DIR [OUT=DIR] [ROSTER=.. SECRET=.. FORMAT=.. ASSIGNMENT=.. DEADLINE=.. PENALTY=.. EXECUTOR=..]"; exit 2)
	$(BIN)/python tools/grade.py --tests solutions/hidden_tests/$(HW_ID).py \
	    --submissions "$(SUBMISSIONS)" --out "$(OUT)" --jobs 2 $(GRADE_OPTS)

# make submit HW=hw01 STUDENT=your-id   (runs the homework fresh, writes submissions/hw01-ID.ipynb)
submit: install
	@test -n "$(STUDENT)" || (echo "usage: make submit HW=hw01 STUDENT=your-id"; exit 2)
	$(BIN)/python -m course_lib.homework.submit "$(HW)" --student "$(STUDENT)"

# make release: the student edition in dist/student-edition/ and dist/student-edition.zip
#   (SECRET=course_secret.txt ROSTER=roster.csv: with answer keys for every student's data)
release: install
	$(BIN)/python tools/release.py --out dist/student-edition $(if $(SECRET),--secret-file "$(SECRET)") $(if $(ROSTER),--roster "$(ROSTER)")

# The website: lectures and blank homework executed (cached in build/site-cache/), demos as
# static figures, MathJax bundled; nothing is loaded from the network.  See site/teaching.md.
site: install
	$(BIN)/python tools/build_site.py

handouts: site
	@bash tools/ensure-browser || true
	$(BIN)/python tools/build_handouts.py

clean:
	rm -rf $(VENV) test-artifacts build/site build/site-src build/site-cache build/site-doctrees build/handouts build/present
