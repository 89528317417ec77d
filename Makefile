# The course's commands.  On a fresh machine (Python 3.10+):
#   make lab    create .venv, install the course, open JupyterLab on notebooks/
#   make test   create .venv, install the course, run the whole test suite
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed

.PHONY: install lab test lint bench grade clean

$(STAMP): pyproject.toml constraints.txt
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -c constraints.txt -e ".[test]"
	touch $@

install: $(STAMP)

lab: install
	$(BIN)/jupyter lab notebooks/

test: install
	@bash tools/ensure-browser || true
	$(BIN)/ruff check course_lib tests benchmarks tools
	$(BIN)/python -m pytest

lint: install
	$(BIN)/ruff check course_lib tests benchmarks tools

bench: install
	$(BIN)/python benchmarks/run.py

clean:
	rm -rf $(VENV) test-artifacts
