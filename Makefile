# Two commands on a fresh machine: `make demo` and `make test`.
PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
STAMP := $(VENV)/.installed
TEST_STAMP := $(VENV)/.installed-test

.PHONY: demo test test-msl bench docs clean

# setup.py builds the compiled step loop (solvers/cbdf*.c): a change there reinstalls
$(STAMP): pyproject.toml setup.py $(wildcard solvers/cbdf*.c solvers/cbdf*.h)
	test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -e ".[plot]"
	touch $(STAMP)

# the test extra brings every optional feature (FMI, io, dask, notebooks) so all are checked
$(TEST_STAMP): $(STAMP)
	$(PY) -m pip install --quiet -e ".[test,plot]"
	touch $(TEST_STAMP)

demo: $(STAMP)
	$(PY) -m acausal.library.examples.motor_drive --plot motor_drive.png

# one worker per core (pytest-xdist): the suite takes half the time on two
test: $(TEST_STAMP)
	$(PY) -m pytest -q -n auto

# every MSL example against its reference result (make test runs a subset of them)
test-msl: $(TEST_STAMP)
	$(PY) -m pytest -q -n auto -m "" tests/msl

bench: $(TEST_STAMP)
	$(PY) benchmarks/run_all.py

# the API reference and the tutorials, into site/ (the docs extra is installed on first use)
docs: $(STAMP)
	@$(PY) -c "import mkdocs, mkdocstrings, material" 2>/dev/null || \
		$(PY) -m pip install --quiet -e ".[docs]" || \
		{ echo "make docs: could not install the docs extra (pip install -e '.[docs]')"; exit 1; }
	$(PY) -m mkdocs build --strict --site-dir site

clean:
	rm -rf $(VENV) build site *.egg-info
